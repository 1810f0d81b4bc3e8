//VTK::System::Dec
// vtkShadowScreenMask: a quad over the whole mask, given in clip space.
in vec4 vertexMC;
void main()
{
  gl_Position = vertexMC;
}
