//VTK::System::Dec
// vtkPlanarReflectionPass: the mirrored scene, one texel per pixel of the
// viewport; the stencil picks the mirror's pixels and the blend colour's
// alpha (R) scales it, added to the mirror's own shading (drawn at 1 - R).
in vec2 texCoord;
uniform sampler2D reflectionColor;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(texture(reflectionColor, texCoord).rgb, 1.0);
}
