// vtkShadowVolumePass: a facet of a closed caster that faces away from a
// light lies in that caster's own shadow (a ray from it towards the light
// enters the solid and must leave through another facet), whatever the
// interpolated normals say near the terminator. The dark-cap volumes leave
// such facets lit (their depth bias keeps the caster's own surface outside
// its volume), so the lighting tests the facet's plane itself: the plane of
// the fragment's triangle from the derivatives of its view-space position,
// turned towards the camera, against the direction to light I.
uniform int vshFacingLights;       // bit I: the actor drawn is a closed caster of light I
uniform vec4 vshFacingLightVC[8];  // light I in view coordinates: (position, 1) or (towards it, 0)
vec3 vshFacetNormalVC = vec3(0.0);
void vshFacingPrepare(vec3 positionVC)
{
  if (vshFacingLights == 0)
  {
    return;
  }
  vec3 n = cross(dFdx(positionVC), dFdy(positionVC));
  vec3 toCamera = cameraParallel == 1 ? vec3(0.0, 0.0, 1.0) : -positionVC;
  vshFacetNormalVC = dot(n, toCamera) < 0.0 ? -n : n;
}
float vshFacingLit(int light, vec3 positionVC)
{
  if ((vshFacingLights & (1 << light)) == 0)
  {
    return 1.0;
  }
  vec4 l = vshFacingLightVC[light];
  vec3 toLight = l.w != 0.0 ? l.xyz - positionVC : l.xyz;
  // A facet within 1e-3 (0.06 degrees) of edge-on keeps the volume's
  // answer: the plane from float derivatives is not better than that.
  float tolerance = 1e-3 * length(vshFacetNormalVC) * length(toLight);
  return dot(vshFacetNormalVC, toLight) < -tolerance ? 0.0 : 1.0;
}
