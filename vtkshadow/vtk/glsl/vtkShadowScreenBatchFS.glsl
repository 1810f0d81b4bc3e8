//VTK::System::Dec
// vtkShadowScreenMask::MarkBatch: after the first batch of a light's
// samples, which pixels get the rest (the stencil test of the draw writes
// the mark where this shader does not discard). The batch's state per
// pixel from the channel's level (vsh_soft_batch_state): 0 all blocked,
// batchLevels all lit, between mixed (each sample adds at least one
// level). As vsh_rt_adaptive_rest_near: a pixel is refined when any pixel
// of its 3x3 neighbourhood is mixed or the neighbourhood holds both all
// lit and all blocked.
uniform sampler2D mask;
uniform int channel;
uniform int batchLevels;
// 1: mark the pixels to refine; 0: mark the others whose batch is all lit.
uniform int refine;
out vec4 maskValue;

int batchState(ivec2 p)
{
  p = clamp(p, ivec2(0), textureSize(mask, 0) - ivec2(1));
  int level = int(floor(texelFetch(mask, p, 0)[channel] * 255.0 + 0.5));
  return level == 0 ? 2 : (level == batchLevels ? 1 : (level < batchLevels ? 3 : 0));
}

void main()
{
  ivec2 p = ivec2(gl_FragCoord.xy);
  bool mixed = false, lit = false, blocked = false;
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      int s = batchState(p + ivec2(dx, dy));
      mixed = mixed || s == 3;
      lit = lit || s == 1;
      blocked = blocked || s == 2;
    }
  }
  bool near = mixed || (lit && blocked);
  if (refine == 1 ? !near : (near || batchState(p) != 1))
  {
    discard;
  }
  maskValue = vec4(0.0);
}
