//VTK::System::Dec
// vtkShadowVolumePass: only the stencil counts; the depth is biased so that
// a volume face lying on the scene's surface (a cap on the caster's own
// face, a side at its silhouette) counts as if the surface point were just
// outside the volume: fragments entering the volume (front faces) move away
// from the camera, fragments leaving it (back faces) towards it. The mapper
// and this shader compute the surface's depth with different vertex code,
// so the bias (window depth units: a constant plus a fraction of the
// depth's slope per pixel, the slope part capped) covers their difference.
// The caps add their caster's coincident-topology offset as its mapper
// computes it (capFactor x the depth's slope + capUnits, vtkShadowVolumePass's
// CoincidentOffset): they lie on the caster's faces themselves.
uniform float depthBias;
uniform float capFactor;
uniform float capUnits;
uniform float slopeBias;
uniform float maxSlopeBias;
out vec4 unused;
void main()
{
  vec2 dz = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
  float slope = max(abs(dz.x), abs(dz.y));
  float bias = depthBias + min(slopeBias * slope, maxSlopeBias);
  bias += capFactor * length(dz) + capUnits;
  gl_FragDepth = gl_FragCoord.z + (gl_FrontFacing ? bias : -bias);
  unused = vec4(0.0);
}
