// vtkShadowScreenMask: each light's visibility of the visible surface, one
// texel per pixel, read once per fragment by vshScreenPrepare() before the
// lighting code; the lighting multiplies light I's terms by vshScreenLight(I).
// Lights 0-3 are the channels of the first texture, 4-7 of the second.
// Where translucent casters filter a light's colour, its tint (RGB, 1 where
// nothing filters) is in the tint texture, light I's rows starting at
// I x the mask's height; vshScreenTinted is 0 when no light is tinted.
uniform sampler2D vshScreenMask0;
uniform sampler2D vshScreenMask1;
uniform ivec2 vshScreenMaskOrigin;
uniform int vshScreenMaskLights;
uniform sampler2D vshScreenTint;
uniform int vshScreenTinted;
uniform int vshScreenMaskHeight;
vec4 vshScreenTexel0 = vec4(1.0);
vec4 vshScreenTexel1 = vec4(1.0);
ivec2 vshScreenPixel = ivec2(0);
void vshScreenPrepare()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy) - vshScreenMaskOrigin;
  vshScreenPixel = pixel;
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
vec3 vshScreenLight(int light)
{
  float lit = vshScreenLit(light);
  if (vshScreenTinted == 0 || light >= vshScreenMaskLights)
  {
    return vec3(lit);
  }
  return lit *
    texelFetch(vshScreenTint, vshScreenPixel + ivec2(0, light * vshScreenMaskHeight), 0).rgb;
}
