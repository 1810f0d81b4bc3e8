// vtkPlanarShadowPass: shadow factors for the mapper's lighting code.
// Inserted after VTK's lighting declarations; the pass multiplies each
// light's diffuse and specular terms (or PBR radiance) by vshPlanarLit(i, ...).
uniform usampler2D vshPlanarMask;
uniform ivec2 vshPlanarMaskOrigin;
// Receiver index of this actor, or -1 for actors that are not receivers.
uniform int vshPlanarReceiver;
// Explicit receiver planes (view coordinates, so camera-relative and
// precise) with their receiver indices and distance tolerances.
uniform int vshPlanarPlaneCount;
uniform vec4 vshPlanarPlaneVC[8];
uniform int vshPlanarPlaneReceiver[8];
uniform float vshPlanarPlaneTolerance[8];
// Number of lights in the mapper's numbering; pair bit = receiver * count + light.
uniform int vshPlanarLightCount;
// The fragment's first mask bit (receiver * light count) and mask bits,
// looked up once per fragment by vshPlanarPrepare() before the lighting code.
// Off receivers the bits stay 0, so every light is unblocked.
uint vshPlanarBase = 0u;
uvec4 vshPlanarBits = uvec4(0u);
#ifdef VSH_PLANAR_SOFT
// Sampled area lights (the pass defines VSH_PLANAR_SOFT only in frames with
// soft pairs, so hard frames run the code above unchanged): channel k of
// vshPlanarSoft holds the shadowed fraction of the soft pair whose bit is
// vshPlanarSoftPair[k] (-1: none).
uniform sampler2D vshPlanarSoft;
uniform int vshPlanarSoftPair[4];
vec4 vshPlanarSoftShadow = vec4(0.0);
#endif
#ifdef VSH_PLANAR_TRANSMIT
// Translucent casters (defined only in frames with translucent casters):
// channel k of vshPlanarTransmit holds the light the translucent casters
// let through to the pair whose bit is vshPlanarTransmitPair[k] (-1: none).
uniform sampler2D vshPlanarTransmit;
uniform int vshPlanarTransmitPair[4];
vec4 vshPlanarTransmitted = vec4(1.0);
#endif
void vshPlanarPrepare(vec3 positionVC)
{
  int receiver = vshPlanarReceiver;
  for (int k = 0; receiver < 0 && k < vshPlanarPlaneCount; ++k)
  {
    float d = dot(vshPlanarPlaneVC[k].xyz, positionVC) + vshPlanarPlaneVC[k].w;
    if (abs(d) <= vshPlanarPlaneTolerance[k] * max(1.0, length(positionVC)))
    {
      receiver = vshPlanarPlaneReceiver[k];
    }
  }
  if (receiver >= 0)
  {
    vshPlanarBase = uint(receiver * vshPlanarLightCount);
    vshPlanarBits = texelFetch(vshPlanarMask, ivec2(gl_FragCoord.xy) - vshPlanarMaskOrigin, 0);
#ifdef VSH_PLANAR_SOFT
    vshPlanarSoftShadow =
      texelFetch(vshPlanarSoft, ivec2(gl_FragCoord.xy) - vshPlanarMaskOrigin, 0);
#endif
#ifdef VSH_PLANAR_TRANSMIT
    vshPlanarTransmitted =
      texelFetch(vshPlanarTransmit, ivec2(gl_FragCoord.xy) - vshPlanarMaskOrigin, 0);
#endif
  }
}
// The opaque casters' part: 0 where light `light` is blocked at this
// fragment, 1 elsewhere (a soft pair: the lit fraction). The pass keeps
// receiver * light count + light below 128.
float vshPlanarOpaqueLit(uint pair)
{
#ifdef VSH_PLANAR_SOFT
  for (int k = 0; k < 4; ++k)
  {
    if (int(pair) == vshPlanarSoftPair[k])
    {
      return clamp(1.0 - vshPlanarSoftShadow[k], 0.0, 1.0);
    }
  }
#endif
  uint word = vshPlanarBits[min(pair >> 5u, 3u)];
  return float(((word >> (pair & 31u)) & 1u) ^ 1u);
}
// The light's factor: the opaque casters' part times what the translucent
// ones let through.
float vshPlanarLit(int light)
{
  uint pair = vshPlanarBase + uint(light);
  float lit = vshPlanarOpaqueLit(pair);
#ifdef VSH_PLANAR_TRANSMIT
  for (int k = 0; k < 4; ++k)
  {
    if (int(pair) == vshPlanarTransmitPair[k])
    {
      lit *= clamp(vshPlanarTransmitted[k], 0.0, 1.0);
    }
  }
#endif
  return lit;
}
