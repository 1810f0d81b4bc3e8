//VTK::System::Dec
// vtkShadowVolumePass: a shadow volume's sides, stencil only. The depth bias
// of vtkShadowVolumeFS is a clamped polygon offset here
// (vtkShadowVolumeSides), so this shader writes no depth and the rasterizer
// tests depth and stencil before it runs; it does nothing.
out vec4 unused;
void main()
{
  unused = vec4(0.0);
}
