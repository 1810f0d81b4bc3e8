// vtkCascadedShadowMapPass, screen-space resolve: one full-screen draw that
// writes, for each pixel of the visible opaque surface, the visibility of up
// to four lights into the channels of a vtkShadowScreenMask texture. It
// follows vtkShadowMapLightFS (the same lookups and uniforms) and a
// generated vshResolveLights(posVC, normalVC, depth) that returns the four
// channels. The mappers then read one texel per light instead of looking up
// the maps for every fragment they rasterize.
uniform sampler2D vshDepth;   // window depth of the opaque scene, [0,1]
uniform mat4 vshNDCToView;    // inverse projection (view space: camera at 0)
uniform vec2 vshMaskSize;     // pixels
out vec4 vshVisibility;

vec3 vshViewPosition(ivec2 p, float d)
{
  vec4 ndc = vec4((vec2(p) + 0.5) / vshMaskSize * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
  vec4 v = vshNDCToView * ndc;
  return v.xyz / v.w;
}

// The neighbour of `pos` towards p + step or p - step whose depth differs
// less: across a silhouette the other side belongs to another surface, and
// a normal from it would point anywhere. Returns (p + step) - p's
// difference vector, or (p - (p - step)); w = 0 when neither side is usable.
vec4 vshTangent(ivec2 p, ivec2 step, vec3 pos)
{
  ivec2 hi = ivec2(vshMaskSize) - 1;
  ivec2 pa = clamp(p + step, ivec2(0), hi);
  ivec2 pb = clamp(p - step, ivec2(0), hi);
  float da = texelFetch(vshDepth, pa, 0).r;
  float db = texelFetch(vshDepth, pb, 0).r;
  vec3 a = vshViewPosition(pa, da);
  vec3 b = vshViewPosition(pb, db);
  float ea = (pa == p || da >= 1.0) ? 1e30 : abs(a.z - pos.z);
  float eb = (pb == p || db >= 1.0) ? 1e30 : abs(pos.z - b.z);
  if (ea >= 1e30 && eb >= 1e30)
  {
    return vec4(0.0);
  }
  return ea <= eb ? vec4(a - pos, 1.0) : vec4(pos - b, 1.0);
}

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  float d = texelFetch(vshDepth, p, 0).r;
  if (d >= 1.0)
  {
    discard; // background: no mapper reads it (and the pass counts the rest)
  }
  vec3 posVC = vshViewPosition(p, d);
  vec4 tx = vshTangent(p, ivec2(1, 0), posVC);
  vec4 ty = vshTangent(p, ivec2(0, 1), posVC);
  vec3 normalVC = -normalize(posVC); // a lone pixel: face the viewer
  if (tx.w > 0.0 && ty.w > 0.0)
  {
    vec3 n = cross(tx.xyz, ty.xyz);
    if (dot(n, n) > 0.0)
    {
      normalVC = normalize(n);
    }
  }
  if (dot(normalVC, posVC) > 0.0)
  {
    normalVC = -normalVC; // towards the viewer, as two-sided lighting does
  }
  vshVisibility = vshResolveLights(posVC, normalVC, -posVC.z);
}
