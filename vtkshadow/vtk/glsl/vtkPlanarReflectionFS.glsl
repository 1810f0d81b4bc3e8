//VTK::System::Dec
// vtkPlanarReflectionPass: the mirrored scene, one texel per pixel of the
// viewport; the stencil picks the mirror's pixels and the blend colour's
// alpha (R) mixes it with the mirror's own shading.
in vec2 texCoord;
uniform sampler2D reflectionColor;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(texture(reflectionColor, texCoord).rgb, 1.0);
}
