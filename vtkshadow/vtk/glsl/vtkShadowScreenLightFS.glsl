// vtkShadowScreenMask: each light's visibility of the visible surface, one
// texel per pixel, read once per fragment by vshScreenPrepare() before the
// lighting code; the lighting multiplies light I's terms by vshScreenLit(I).
// Lights 0-3 are the channels of the first texture, 4-7 of the second.
uniform sampler2D vshScreenMask0;
uniform sampler2D vshScreenMask1;
uniform ivec2 vshScreenMaskOrigin;
uniform int vshScreenMaskLights;
vec4 vshScreenTexel0 = vec4(1.0);
vec4 vshScreenTexel1 = vec4(1.0);
void vshScreenPrepare()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy) - vshScreenMaskOrigin;
  vshScreenTexel0 = texelFetch(vshScreenMask0, pixel, 0);
  if (vshScreenMaskLights > 4)
  {
    vshScreenTexel1 = texelFetch(vshScreenMask1, pixel, 0);
  }
}
float vshScreenLit(int light)
{
  if (light >= vshScreenMaskLights)
  {
    return 1.0;
  }
  return light < 4 ? vshScreenTexel0[light] : vshScreenTexel1[light - 4];
}
