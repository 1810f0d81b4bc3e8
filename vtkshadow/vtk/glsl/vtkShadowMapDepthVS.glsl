//VTK::System::Dec
// vtkCascadedShadowMapPass: a caster into one shadow map. The matrix takes
// the caster's positions (relative to its data centre) to the map's clip
// space in one step, computed in double on the CPU.
in vec4 vertexMC;
uniform mat4 mapMCDC;
void main()
{
  gl_Position = mapMCDC * vertexMC;
}
