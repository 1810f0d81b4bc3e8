// vtkCascadedShadowMapPass: shadow factors for the mapper's lighting code.
// Inserted after VTK's lighting declarations, after the pass's #defines
// (VSH_FILTER: 0 hardware 2x2, 1 NxN PCF, 2 Poisson; VSH_PCF_HALF; VSH_PCSS
// with VSH_PCSS_BLOCKER_TAPS, VSH_PCSS_FILTER_TAPS, VSH_PCSS_MAX_TEXELS in
// frames where a casting light has a size; VSH_TRANSMIT in frames with a
// translucent caster) and
// followed by a generated vshShadowPrepare() that calls vshShadowCascades,
// vshShadowSpot or vshShadowPoint for each light that casts, with the
// light's atlas tiles as literals. The filter and
// the lights' kinds are compiled in, not branched on: a software rasterizer
// runs both sides of a branch, so uniform switches cost every path.
uniform sampler2DShadow vshShadowAtlas;
uniform vec2 vshAtlasTexel;          // one atlas texel in texture coordinates
uniform int vshShadowLightCount;     // lights in the mapper's numbering
uniform int vshShadowKind[8];        // 0 none, 1 cascades, 2 spot, 3 point (cube)
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
#ifdef VSH_PCSS
uniform sampler2D vshShadowAtlasRaw; // the same atlas, no depth comparison
uniform vec2 vshTileSoft[24];        // (size term, depth scale) per map: x tan(angle / 2)
                                     // (directional) or radius (positional), 0 hard; y the
                                     // depth range (orthographic, world) or near distance
#endif
#ifdef VSH_SAMPLED
uniform vec2 vshSampleDisk[VSH_SAMPLES]; // the stratified points on the unit disk
uniform vec3 vshSampleU[8];          // positional: radius x the disk's axes, view coordinates
uniform vec3 vshSampleV[8];
uniform vec4 vshTileShear[24];       // directional: clip shear per unit of disk sample
uniform int vshAtlasColumns;         // the atlas grid (sample slots have no uniforms)
uniform vec2 vshAtlasTile;           // one tile's size in texture coordinates
#endif
#ifdef VSH_TRANSMIT
// The translucent casters, beside the atlas in the same layout: their
// nearest depth (compared like the atlas) and the product of (1 - opacity)
// over their surfaces in front of the opaque map (linear filtering).
uniform sampler2DShadow vshTranslucentAtlas;
uniform sampler2D vshTransmitAtlas;
#endif
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

#ifdef VSH_PCSS
// Sample k of n on the unit disk, stratified by area (Vogel's golden-angle
// spiral, as vsh_soft_disk_sample), turned by `turn` radians.
vec2 vshVogel(int k, int n, float turn)
{
  float a = float(k) * 2.39996323 + turn;
  return sqrt((float(k) + 0.5) / float(n)) * vec2(cos(a), sin(a));
}

// A per-pixel rotation of the disk (interleaved gradient noise): few taps
// then give noise instead of the banding of one fixed pattern.
float vshPCSSTurn()
{
  return 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// Map position of a view-space point: (atlas uv, window depth).
vec3 vshMapPoint(int tile, vec3 q)
{
  vec4 c = vshTileMatrix[tile] * vec4(q, 1.0);
  vec3 n = c.xyz / c.w;
  vec4 rect = vshTileRect[tile];
  return vec3(rect.xy + (n.xy * 0.5 + 0.5) * rect.zw, n.z * 0.5 + 0.5);
}

// Receiver plane depth bias (Isidoro 2006): the change of the receiver's
// map depth per unit of atlas uv, from two steps of `eps` along the surface
// at p. A wide kernel over a surface sloped in the map would otherwise
// shadow the surface with itself. 0 where the surface is edge-on to the
// light (its terms are 0 there anyway).
vec2 vshReceiverPlane(int tile, vec3 p, vec3 n, float eps)
{
  vec3 a = abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  vec3 t1 = normalize(cross(n, a));
  vec3 t2 = cross(n, t1);
  vec3 q0 = vshMapPoint(tile, p);
  vec3 d1 = vshMapPoint(tile, p + t1 * eps) - q0;
  vec3 d2 = vshMapPoint(tile, p + t2 * eps) - q0;
  float det = d1.x * d2.y - d1.y * d2.x;
  if (abs(det) <= 1e-3 * (dot(d1.xy, d1.xy) + dot(d2.xy, d2.xy)))
  {
    return vec2(0.0);
  }
  return vec2(d1.z * d2.y - d2.z * d1.y, d1.x * d2.z - d2.x * d1.z) / det;
}

// Distance along the light of a raw map depth z (window, 0..1): from the
// near plane (orthographic), from the light (perspective: ndc z = -x + y / d
// with x = -(f + n) / (f - n) and y = -2 f n / (f - n), both negative, so
// the denominator is negative for every depth in the map).
float vshMapDistance(int tile, float z, bool perspective)
{
  vec2 pz = vshTileDepth[tile];
  return perspective ? pz.y / min(z * 2.0 - 1.0 + pz.x, -1e-30) : z * vshTileSoft[tile].y;
}

// PCSS (Fernando 2005) for map `tile` at atlas `uv`, reference depth `ref`
// (biased), receiver distance `dr` along the light: blockers searched over
// the half-width a blocker at the map's near plane would give (every
// blocker the receiver sees is inside it), then a filter of the half-width
// their mean distance gives: vsh_pcss_sun_halfwidth (directional, world)
// or vsh_pcss_disk_halfwidth (per unit distance), over the map's texel
// (vshTileTexel: world, or at distance 1), clamped to VSH_PCSS_MAX_TEXELS
// and to the tile.
float vshShadowPCSS(int tile, vec3 p, vec3 normalVC, vec2 uv, vec2 lo, vec2 hi, float ref,
  float dr, bool perspective, float reach)
{
  vec2 soft = vshTileSoft[tile];
  float texel = vshTileTexel[tile];
  vec2 grad = vshReceiverPlane(tile, p, normalVC, texel * reach);
  float search = perspective ? soft.x * max(1.0 / soft.y - 1.0 / dr, 0.0) : soft.x * dr;
  vec2 searchUV = min(search / texel, VSH_PCSS_MAX_TEXELS) * vshAtlasTexel;
  float turn = vshPCSSTurn();
  float blockers = 0.0;
  float sumD = 0.0;
  for (int k = 0; k < VSH_PCSS_BLOCKER_TAPS; ++k)
  {
    vec2 offset = vshVogel(k, VSH_PCSS_BLOCKER_TAPS, turn) * searchUV;
    float z = texture(vshShadowAtlasRaw, clamp(uv + offset, lo, hi)).r;
    if (z < ref + dot(grad, offset))
    {
      blockers += 1.0;
      sumD += vshMapDistance(tile, z, perspective);
    }
  }
  if (blockers == 0.0)
  {
    return 1.0;
  }
  float db = sumD / blockers;
  float width = perspective ? soft.x * max(1.0 / db - 1.0 / dr, 0.0) : soft.x * max(dr - db, 0.0);
  vec2 kernelUV = min(width / texel, VSH_PCSS_MAX_TEXELS) * vshAtlasTexel;
  float sum = 0.0;
  for (int k = 0; k < VSH_PCSS_FILTER_TAPS; ++k)
  {
    vec2 offset = vshVogel(k, VSH_PCSS_FILTER_TAPS, turn + 1.0) * kernelUV;
    sum += texture(vshShadowAtlas, vec3(clamp(uv + offset, lo, hi), ref + dot(grad, offset)));
  }
  return sum / float(VSH_PCSS_FILTER_TAPS);
}
#endif

// What the translucent casters let through to a receiver at atlas `uv`
// (inside its tile), biased reference depth `ref`: 1 where the receiver is
// nearer the light than every translucent surface of the texel (the same
// comparison, bias and 2x2 filtering as the opaque map's), else the texel's
// product of (1 - opacity), read bilinearly. A receiver between two
// translucent surfaces gets the whole product.
float vshTransmittance(vec2 uv, float ref)
{
#ifdef VSH_TRANSMIT
  float front = texture(vshTranslucentAtlas, vec3(uv, ref));
  return mix(texture(vshTransmitAtlas, uv).r, 1.0, front);
#else
  return 1.0;
#endif
}

float vshShadowFiltered(int tile, vec3 posVC, vec3 p, vec3 normalVC, vec2 uv, vec2 lo, vec2 hi,
  float ref, float w, bool perspective, float reach);

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
  return vshShadowFiltered(tile, posVC, p, normalVC, uv, lo, hi, ref, clip.w, perspective, reach) *
    vshTransmittance(clamp(uv, lo, hi), ref);
}

// The opaque map's filtered comparison for vshShadowSample: the receiver at
// posVC (p: moved by the normal offset) is at atlas `uv` (inside lo..hi),
// biased reference depth `ref`, clip w `w`.
float vshShadowFiltered(int tile, vec3 posVC, vec3 p, vec3 normalVC, vec2 uv, vec2 lo, vec2 hi,
  float ref, float w, bool perspective, float reach)
{
#ifdef VSH_PCSS
  if (vshTileSoft[tile].x > 0.0)
  {
    float dr = perspective ? w : ref * vshTileSoft[tile].y;
    return vshShadowPCSS(tile, p, normalVC, uv, lo, hi, ref, dr, perspective, reach);
  }
#endif
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

// Directional light: its cascade for this depth, blended into the next one
// across the blend band. `first` and `count` are literals in the generated
// call (CascadedLookupCode): a light with one cascade then indexes every
// uniform array with a constant, which a software rasterizer reads once per
// draw; the cascade of a light with several is chosen per pixel (an index
// per pixel, a gather: still cheaper than branches, which llvmpipe runs on
// every path).
float vshShadowCascades(int first, int count, float depth, vec3 posVC, vec3 normalVC)
{
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

float vshShadowSpot(int first, vec3 posVC, vec3 normalVC)
{
  return vshShadowSample(first, posVC, normalVC, true);
}

// Point light `l` (its six maps from atlas tile `first`, a literal in the
// generated call): the cube face of the direction's major axis.
float vshShadowPoint(int l, int first, vec3 posVC, vec3 normalVC)
{
  vec3 d = vshViewToWorld * (posVC - vshShadowLightVC[l]);
  vec3 a = abs(d);
  int face = (a.x >= a.y && a.x >= a.z) ? (d.x >= 0.0 ? 0 : 1)
    : (a.y >= a.z)                      ? (d.y >= 0.0 ? 2 : 3)
                                        : (d.z >= 0.0 ? 4 : 5);
  return vshShadowSample(first + face, posVC, normalVC, true);
}

#ifdef VSH_SAMPLED
// SOFT_SAMPLED: the hard comparison of one sample map, from the uniforms of
// its base map `tile` (a literal where the caller has one) and the sample's
// eye offset `offsetVC` (spot, point: the map moved to the point on the
// light) or clip shear (directional: x, y -= shear clip z), in atlas slot
// `slot`. The same bias as the hard lookup.
float vshSampleMap(int tile, int slot, vec3 offsetVC, vec2 shear, vec3 posVC, vec3 normalVC,
  bool perspective)
{
  vec2 bias = vshTileBias[tile];
  vec3 q = posVC - offsetVC;
  float reach = perspective ? max((vshTileMatrix[tile] * vec4(q, 1.0)).w, 0.0) : 1.0;
  vec4 clip = vshTileMatrix[tile] * vec4(q + normalVC * (bias.y * reach), 1.0);
  clip.xy -= shear * clip.z;
  if (clip.w <= 0.0)
  {
    return 1.0;
  }
  vec3 ndc = clip.xyz / clip.w;
  if (abs(ndc.x) > 1.0 || abs(ndc.y) > 1.0 || ndc.z > 1.0)
  {
    return 1.0;
  }
  int row = slot / vshAtlasColumns;
  vec2 origin = vec2(float(slot - row * vshAtlasColumns), float(row)) * vshAtlasTile;
  vec2 uv = origin + (ndc.xy * 0.5 + 0.5) * vshAtlasTile;
  vec2 lo = origin + 0.5 * vshAtlasTexel;
  vec2 hi = origin + vshAtlasTile - 0.5 * vshAtlasTexel;
  float ref;
  if (perspective)
  {
    vec2 pz = vshTileDepth[tile];
    ref = clamp((-pz.x + pz.y / (clip.w * (1.0 - bias.x))) * 0.5 + 0.5, 0.0, 1.0);
  }
  else
  {
    ref = clamp(ndc.z * 0.5 + 0.5 - bias.x, 0.0, 1.0);
  }
  vec2 at = clamp(uv, lo, hi);
  return texture(vshShadowAtlas, vec3(at, ref)) * vshTransmittance(at, ref);
}

// Adaptive counts (VSH_SAMPLE_BATCH > 0): range holds the lowest and highest
// comparison so far; after the batch (the light's centre and rim, the first
// VSH_SAMPLE_BATCH samples) true where every one was fully lit or fully
// blocked, and range.x is then that answer. The hardware 2x2 comparison
// reads fractions near any sample's shadow edge, so such pixels continue.
bool vshBatchAgrees(int k, float lit, inout vec2 range)
{
  range = vec2(min(range.x, lit), max(range.y, lit));
  return k == VSH_SAMPLE_BATCH - 1 && (range.y <= 1e-4 || range.x >= 1.0 - 1e-4);
}

// The mean of light l's VSH_SAMPLES sample maps of map `tile`: sample k in
// slot slot0 + k stride.
float vshShadowSampled(int l, int tile, int slot0, int stride, vec3 posVC, vec3 normalVC,
  bool perspective)
{
  vec4 s = vshTileShear[tile];
  float sum = 0.0;
  vec2 range = vec2(1.0, 0.0);
  for (int k = 0; k < VSH_SAMPLES; ++k)
  {
    vec2 q = vshSampleDisk[k];
    float lit = vshSampleMap(tile, slot0 + k * stride, q.x * vshSampleU[l] + q.y * vshSampleV[l],
      q.x * s.xy + q.y * s.zw, posVC, normalVC, perspective);
    sum += lit;
    if (vshBatchAgrees(k, lit, range))
    {
      return range.x;
    }
  }
  return sum / float(VSH_SAMPLES);
}

// vshShadowCascades with each cascade's samples (cascade c of sample k in
// slot slot0 + k count + c).
float vshShadowCascadesSampled(
  int l, int first, int count, int slot0, float depth, vec3 posVC, vec3 normalVC)
{
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
  float lit = vshShadowSampled(l, first + c, slot0 + c, count, posVC, normalVC, false);
  if (c < count - 1 && vshBlendBand > 0.0)
  {
    float nearD = c == 0 ? 0.0 : vshTileFar[first + c - 1];
    float farD = vshTileFar[first + c];
    float w = smoothstep(farD - vshBlendBand * (farD - nearD), farD, depth);
    if (w > 0.0)
    {
      lit = mix(lit,
        vshShadowSampled(l, first + c + 1, slot0 + c + 1, count, posVC, normalVC, false), w);
    }
  }
  return lit;
}

// A point light's samples: each sample point picks its own cube face.
float vshShadowPointSampled(int l, int first, int slot0, vec3 posVC, vec3 normalVC)
{
  float sum = 0.0;
  vec2 range = vec2(1.0, 0.0);
  for (int k = 0; k < VSH_SAMPLES; ++k)
  {
    vec2 q = vshSampleDisk[k];
    vec3 o = q.x * vshSampleU[l] + q.y * vshSampleV[l];
    vec3 d = vshViewToWorld * (posVC - vshShadowLightVC[l] - o);
    vec3 a = abs(d);
    int face = (a.x >= a.y && a.x >= a.z) ? (d.x >= 0.0 ? 0 : 1)
      : (a.y >= a.z)                      ? (d.y >= 0.0 ? 2 : 3)
                                          : (d.z >= 0.0 ? 4 : 5);
    float lit = vshSampleMap(first + face, slot0 + k * 6 + face, o, vec2(0.0), posVC, normalVC, true);
    sum += lit;
    if (vshBatchAgrees(k, lit, range))
    {
      return range.x;
    }
  }
  return sum / float(VSH_SAMPLES);
}
#endif

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
