//VTK::System::Dec
// vtkShadowVolumePass: a shadow volume's triangles. vertexMC is homogeneous:
// w = 1 for a vertex of the caster (relative to its data centre), w = 0 for
// its extrusion to infinity away from the light. The whole chain (model ->
// world -> relative to the eye -> clip) is one matrix made in double on the
// CPU, so nothing large reaches float.
in vec4 vertexMC;
uniform mat4 volumeMCDC;
void main()
{
  gl_Position = volumeMCDC * vertexMC;
}
