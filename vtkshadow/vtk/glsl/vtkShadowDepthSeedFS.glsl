//VTK::System::Dec
// vtkShadowDepthSeed: the depth pre-pass's depth into the main pass's
// framebuffer, one step of a 24-bit depth buffer deeper, so that the visible
// fragment still passes a LEQUAL test whatever the target's depth format.
uniform sampler2D seedDepth;
uniform ivec2 seedOrigin;
out vec4 seedUnused;
void main()
{
  float depth = texelFetch(seedDepth, ivec2(gl_FragCoord.xy) - seedOrigin, 0).r;
  if (depth >= 1.0)
  {
    discard; // the cleared depth already says so: no write
  }
  gl_FragDepth = min(depth + 1.0 / 16777215.0, 1.0);
  seedUnused = vec4(0.0);
}
