//VTK::System::Dec
// vtkShadowVolumeOpacityMap: one light's channel of a vtkShadowScreenMask
// times the light the volumes keep at each visible pixel. The pixel's view
// position comes from the mask's depth (as csm's resolve finds it), goes
// into the map's light frame, and the four nearest texels' transmittances
// at the pixel's light distance are interpolated bilinearly: each texel's
// own (T, entry, exit) at that distance, so a texel whose ray misses the
// boxes (entry "none") blends as 1 instead of as a huge distance.
// Blending (GL_ZERO, GL_SRC_COLOR) with only the light's channel written
// does the multiply.
uniform sampler2D vshDepth;   // window depth of the scene, [0,1]
uniform sampler2D vshMap;     // (T, entry, exit, 0) per texel, RGBA32F
uniform mat4 vshNDCToView;    // inverse projection (view space: camera at 0)
uniform mat4 vshViewToMap;    // view -> the map's (u, v, w)
uniform vec2 vshMaskSize;     // pixels
uniform vec4 vshMapWindow;    // lo (s, t), hi (s, t)
uniform vec2 vshMapSize;      // texels
uniform int vshPerspective;   // 1: (s, t) = (u, v) / w, distance |(u, v, w)|
out vec4 vshVisibility;

float vshKept(ivec2 texel, float d)
{
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(vshMapSize))))
  {
    return 1.0; // beside the map: beside every box
  }
  vec4 m = texelFetch(vshMap, texel, 0);
  if (d <= m.y)
  {
    return 1.0;
  }
  if (d >= m.z)
  {
    return m.x;
  }
  // Inside the crossing: the optical depth taken as even along it.
  return pow(m.x, (d - m.y) / (m.z - m.y));
}

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(vshDepth, p, 0).r;
  if (depth >= 1.0)
  {
    discard; // background
  }
  vec4 ndc = vec4((vec2(p) + 0.5) / vshMaskSize * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec4 v = vshNDCToView * ndc;
  vec3 q = (vshViewToMap * vec4(v.xyz / v.w, 1.0)).xyz;
  vec2 s = q.xy;
  float d = q.z;
  if (vshPerspective != 0)
  {
    if (q.z <= 0.0)
    {
      discard; // behind the light: no box there
    }
    s = q.xy / q.z;
    d = length(q);
  }
  vec2 f = (s - vshMapWindow.xy) / (vshMapWindow.zw - vshMapWindow.xy) * vshMapSize - 0.5;
  vec2 i0 = floor(f);
  vec2 w = f - i0;
  ivec2 t = ivec2(i0);
  float k00 = vshKept(t, d), k10 = vshKept(t + ivec2(1, 0), d);
  float k01 = vshKept(t + ivec2(0, 1), d), k11 = vshKept(t + ivec2(1, 1), d);
  vshVisibility = vec4(mix(mix(k00, k10, w.x), mix(k01, k11, w.x), w.y));
}
