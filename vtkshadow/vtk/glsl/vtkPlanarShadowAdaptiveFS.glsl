//VTK::System::Dec
// vtkPlanarShadowPass, adaptive sample counts: after the batch of a soft
// pair, its mark (vsh_soft_mark_pixels, one byte per pixel: 0 batch all
// lit, 1 all blocked, 2 refine) sets the pixels that keep the batch's
// answer to exactly 0 or 1 shadowed (the colour mask selects the pair's
// channel) and writes their depth (0 by the depth range), so the rest of the
// samples, drawn with a depth test, reach only the refined pixels, whose
// depth stays cleared to 1 (this shader discards them, keeping their sum).
uniform sampler2D batchMark;
out vec4 shadowShare;
void main()
{
  float mark = texelFetch(batchMark, ivec2(gl_FragCoord.xy), 0).r * 255.0;
  if (mark > 1.5)
  {
    discard;
  }
  shadowShare = vec4(mark > 0.5 ? 1.0 : 0.0);
}
