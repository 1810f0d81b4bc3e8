// The facing test (vtkShadowFacingTest.h), for vtkShadowVolumePass and
// vtkPlanarShadowPass: a facet of a closed caster that faces away from a
// light lies in that caster's own shadow (a ray from it towards the light
// enters the solid and must leave through another facet), whatever the
// interpolated normals say near the terminator. Neither the dark-cap
// volumes (their depth bias keeps a caster's own surface outside its
// volume) nor planar's receiver mask darken such facets, so the lighting
// tests the facet's plane itself: the plane of the fragment's triangle from
// the derivatives of its view-space position, turned towards the camera,
// against the direction to light I. Each pass declares its own copy: every
// name starting with "vshFacing" is renamed to the pass's prefix
// (vtkshadow::FacingShaderCode), so two passes in one shader (auto's
// chain) keep their uniforms apart.
uniform int vshFacingLights;       // bit I: the actor drawn is a closed caster of light I
uniform vec4 vshFacingLightVC[8];  // light I in view coordinates: (position, 1) or (towards it, 0)
// Light I sampled (soft_samples > 1): its radius, or tan(angle / 2) of a
// directional light; 0 for a light counted hard.
uniform float vshFacingLightSize[8];
vec3 vshFacingNormalVC = vec3(0.0);
void vshFacingPrepare(vec3 positionVC)
{
  if (vshFacingLights == 0)
  {
    return;
  }
  vec3 n = cross(dFdx(positionVC), dFdy(positionVC));
  vec3 toCamera = cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -positionVC;
  vshFacingNormalVC = dot(n, toCamera) < 0.0 ? -n : n;
}
float vshFacingLit(int light, vec3 positionVC)
{
  if ((vshFacingLights & (1 << light)) == 0)
  {
    return 1.0;
  }
  vec4 l = vshFacingLightVC[light];
  vec3 toLight = l.w != 0.0 ? l.xyz - positionVC : l.xyz;
  float size = vshFacingLightSize[light];
  if (size > 0.0)
  {
    // A light with a size: the fraction of it in front of the facet's
    // plane, exactly, for the light the scene defines (a disk of radius
    // `size` facing this point, or directions l + size q, q in the unit disk
    // perpendicular to l). Its points' heights over the plane are
    // h + rho x, h the centre's, rho = size |n x axis|, and x of a uniform
    // disk has the semicircle density: the fraction above 0 is
    // 1/2 + (t sqrt(1 - t^2) + asin t) / pi, t = h / rho clamped to [-1, 1].
    // No hard terminator: it fades over the facets that see part of the
    // light. vshFacingCombine takes the smaller of this and the mask.
    vec3 n = normalize(vshFacingNormalVC);
    vec3 axis = normalize(toLight);
    float h = dot(n, l.w != 0.0 ? toLight : axis);
    float rho = size * length(cross(n, axis));
    if (rho > 1e-6 * max(abs(h), 1e-30))
    {
      float t = clamp(h / rho, -1.0, 1.0);
      return 0.5 + (t * sqrt(1.0 - t * t) + asin(t)) / 3.14159265358979;
    }
  }
  // A facet within 1e-4 (0.006 degrees) of edge-on keeps the pass's
  // answer: the plane from float derivatives of view-space positions is
  // good to a few 1e-5 (their rounding over a pixel's step). A wider margin
  // leaves whole facets wrong: cad/table-parts' tall cylinder has one that
  // faces away from light 0 by 5.4e-4.
  float tolerance = 1e-4 * length(vshFacingNormalVC) * length(toLight);
  return dot(vshFacingNormalVC, toLight) < -tolerance ? 0.0 : 1.0;
}

// Light I's factor from the mask's value (planar passes 1: its mask is not
// on casters): times the facing test for a light counted hard (0 or 1). For
// a sampled light, the visibility is that of the part of the light the facet
// can see: samples behind the facet's plane send it no light, lit or not
// (Cycles weights each sample by its N.L, and raytrace does too), while the samples' volumes count them as blocked (the
// caster shadows its own back: measured on sphere-disk, the mask alone 0.53
// on the terminator where the facing fraction is about as much). So the
// mask is divided by the facing fraction: about 1 on a convex caster's
// terminator, unchanged where the whole light is in front (fraction 1,
// every receiver). A facet that sees none of the light gets none of it.
float vshFacingCombine(int light, vec3 positionVC, float screen)
{
  float facing = vshFacingLit(light, positionVC);
  if (vshFacingLightSize[light] > 0.0)
  {
    return facing > 0.0 ? min(screen / facing, 1.0) : 0.0;
  }
  return screen * facing;
}
