// vtkCascadedShadowMapPass: shadow factors for the mapper's lighting code.
// Inserted after VTK's lighting declarations, after the pass's #defines
// (VSH_FILTER: 0 hardware 2x2, 1 NxN PCF, 2 Poisson; VSH_PCF_HALF) and
// followed by a generated vshShadowPrepare() that calls vshShadowCascades,
// vshShadowSpot or vshShadowPoint for each light that casts. The filter and
// the lights' kinds are compiled in, not branched on: a software rasterizer
// runs both sides of a branch, so uniform switches cost every path.
uniform sampler2DShadow vshShadowAtlas;
uniform vec2 vshAtlasTexel;          // one atlas texel in texture coordinates
uniform int vshShadowLightCount;     // lights in the mapper's numbering
uniform int vshShadowKind[8];        // 0 none, 1 cascades, 2 spot, 3 point (cube)
uniform int vshShadowFirst[8];       // first map of the light
uniform int vshShadowCount[8];       // number of cascades (kind 1)
uniform vec3 vshShadowLightVC[8];    // light position in view coordinates (kind 3)
uniform mat4 vshTileMatrix[24];      // view coordinates -> map clip space
uniform vec4 vshTileRect[24];        // atlas rectangle: offset.xy, size.zw
uniform vec2 vshTileBias[24];        // depth bias, normal offset: 0..1 depth and world
                                     // units (orthographic); per unit distance (perspective)
uniform vec2 vshTileDepth[24];       // perspective: ndc z = -x + y / distance
uniform float vshTileFar[24];        // far depth of each cascade (kind 1)
uniform float vshTileTexel[24];      // world size of a texel (at distance 1: perspective)
uniform vec4 vshShadowToLightVC[8];  // (direction to the light, 0) or (position VC, 1)
uniform vec2 vshPixelSize;           // world size of a pixel: x + y * view depth
uniform mat3 vshViewToWorld;         // view -> world rotation (cube face choice)
uniform float vshPoissonRadius;
uniform float vshBlendBand;
uniform float vshShadowMaxDistance;  // 0: none
uniform float vshShadowFadeStart;
uniform int vshDebugCascades;
float vshShadowFactor[8];
int vshShadowCascadeShown = -1;

const vec2 vshPoissonDisc[16] = vec2[](
  vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725),
  vec2(-0.09418410, -0.92938870), vec2(0.34495938, 0.29387760),
  vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
  vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379),
  vec2(0.44323325, -0.97511554), vec2(0.53742981, -0.47373420),
  vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
  vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590),
  vec2(0.19984126, 0.78641367), vec2(0.14383161, -0.14100790));

// Whether the surface at posVC with normal normalVC faces light `l` by
// more than `margin` (cosine). The mapper's diffuse and specular terms of a
// light the surface faces away from are 0, so no lookup is needed there.
bool vshShadowFacing(int l, vec3 posVC, vec3 normalVC, float margin)
{
  vec4 light = vshShadowToLightVC[l];
  vec3 toLight = light.xyz - posVC * light.w;
  return dot(normalVC, toLight) > margin * length(toLight);
}

// Fraction of the light reaching the fragment according to map `tile`
// (perspective: a spot or point-light map, whose texels grow with distance).
float vshShadowSample(int tile, vec3 posVC, vec3 normalVC, bool perspective)
{
  vec2 bias = vshTileBias[tile];
  float reach = 1.0;
  if (perspective)
  {
    reach = max((vshTileMatrix[tile] * vec4(posVC, 1.0)).w, 0.0);
  }
  vec3 p = posVC + normalVC * (bias.y * reach);
  vec4 clip = vshTileMatrix[tile] * vec4(p, 1.0);
  if (clip.w <= 0.0)
  {
    return 1.0;
  }
  vec3 ndc = clip.xyz / clip.w;
  if (abs(ndc.x) > 1.0 || abs(ndc.y) > 1.0 || ndc.z > 1.0)
  {
    return 1.0; // outside the map: nothing casts there
  }
  vec4 rect = vshTileRect[tile];
  vec2 uv = rect.xy + (ndc.xy * 0.5 + 0.5) * rect.zw;
  // Stay half a texel inside the tile: filtering must not read a neighbour.
  vec2 lo = rect.xy + 0.5 * vshAtlasTexel;
  vec2 hi = rect.xy + rect.zw - 0.5 * vshAtlasTexel;
  float ref;
  if (perspective)
  {
    // Towards the light by a fraction of the distance, in linear depth.
    vec2 pz = vshTileDepth[tile];
    ref = clamp((-pz.x + pz.y / (clip.w * (1.0 - bias.x))) * 0.5 + 0.5, 0.0, 1.0);
  }
  else
  {
    ref = clamp(ndc.z * 0.5 + 0.5 - bias.x, 0.0, 1.0);
  }
#if VSH_FILTER == 0
  return texture(vshShadowAtlas, vec3(clamp(uv, lo, hi), ref));
#else
  // Filter taps by the texel footprint: where one texel covers more than
  // VSH_TAP_TEXEL_PX pixels the hardware 2x2 comparison already ramps
  // smoothly across the edge, and taps only widen it.
  float texelWorld = vshTileTexel[tile] * reach;
  float pixelWorld = vshPixelSize.x + vshPixelSize.y * (-posVC.z);
  if (texelWorld > VSH_TAP_TEXEL_PX * pixelWorld)
  {
    return texture(vshShadowAtlas, vec3(clamp(uv, lo, hi), ref));
  }
#endif
#if VSH_FILTER == 1
  float sum = 0.0;
  for (int i = -VSH_PCF_HALF; i <= VSH_PCF_HALF; ++i)
  {
    for (int j = -VSH_PCF_HALF; j <= VSH_PCF_HALF; ++j)
    {
      sum += texture(vshShadowAtlas,
        vec3(clamp(uv + vec2(float(i), float(j)) * vshAtlasTexel, lo, hi), ref));
    }
  }
  return sum / float((2 * VSH_PCF_HALF + 1) * (2 * VSH_PCF_HALF + 1));
#elif VSH_FILTER == 2
  float sum = 0.0;
  for (int k = 0; k < 16; ++k)
  {
    vec2 offset = vshPoissonDisc[k] * vshPoissonRadius * vshAtlasTexel;
    sum += texture(vshShadowAtlas, vec3(clamp(uv + offset, lo, hi), ref));
  }
  return sum / 16.0;
#endif
}

// Directional light `l`: its cascade for this depth, blended into the next
// one across the blend band.
float vshShadowCascades(int l, float depth, vec3 posVC, vec3 normalVC)
{
  int first = vshShadowFirst[l];
  int count = vshShadowCount[l];
  if (depth > vshTileFar[first + count - 1])
  {
    return 1.0;
  }
  int c = 0;
  while (c < count - 1 && depth > vshTileFar[first + c])
  {
    ++c;
  }
  if (vshShadowCascadeShown < 0)
  {
    vshShadowCascadeShown = c;
  }
  float lit = vshShadowSample(first + c, posVC, normalVC, false);
  if (c < count - 1 && vshBlendBand > 0.0)
  {
    float nearD = c == 0 ? 0.0 : vshTileFar[first + c - 1];
    float farD = vshTileFar[first + c];
    float w = smoothstep(farD - vshBlendBand * (farD - nearD), farD, depth);
    if (w > 0.0)
    {
      lit = mix(lit, vshShadowSample(first + c + 1, posVC, normalVC, false), w);
    }
  }
  return lit;
}

float vshShadowSpot(int l, vec3 posVC, vec3 normalVC)
{
  return vshShadowSample(vshShadowFirst[l], posVC, normalVC, true);
}

// Point light `l`: the cube face of the direction's major axis.
float vshShadowPoint(int l, vec3 posVC, vec3 normalVC)
{
  vec3 d = vshViewToWorld * (posVC - vshShadowLightVC[l]);
  vec3 a = abs(d);
  int face = (a.x >= a.y && a.x >= a.z) ? (d.x >= 0.0 ? 0 : 1)
    : (a.y >= a.z)                      ? (d.y >= 0.0 ? 2 : 3)
                                        : (d.z >= 0.0 ? 4 : 5);
  return vshShadowSample(vshShadowFirst[l] + face, posVC, normalVC, true);
}

float vshShadowFade(float depth)
{
  return vshShadowMaxDistance > 0.0
    ? 1.0 - smoothstep(vshShadowFadeStart, vshShadowMaxDistance, depth)
    : 1.0;
}

vec3 vshCascadeTint(int c)
{
  const vec3 tints[8] = vec3[](vec3(1.0, 0.55, 0.55), vec3(0.55, 1.0, 0.55),
    vec3(0.55, 0.55, 1.0), vec3(1.0, 1.0, 0.55), vec3(1.0, 0.55, 1.0), vec3(0.55, 1.0, 1.0),
    vec3(1.0, 0.8, 0.5), vec3(0.7, 0.7, 0.7));
  return tints[c % 8];
}
