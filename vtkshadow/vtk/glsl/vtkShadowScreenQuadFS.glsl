//VTK::System::Dec
// vtkShadowScreenMask: write one value; the colour mask picks the light's
// channel and the stencil test picks the pixels.
uniform vec4 value;
out vec4 maskValue;
void main()
{
  maskValue = value;
}
