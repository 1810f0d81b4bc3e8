//VTK::System::Dec
// vtkPlanarShadowPass: project a caster onto a receiver plane from a light.
//
// vertexMC is the caster's position relative to its data centre. The whole
// chain (model -> world -> relative to the eye -> projected onto the plane ->
// clip space) is one matrix computed in double precision on the CPU, so
// nothing large ever reaches float.
in vec4 vertexMC;
uniform mat4 shadowMCDC;
// Keep-where-non-negative planes, in the same model coordinates:
// 0: the caster is on the lit side of the receiver (parts behind it cast nothing)
// 1: the caster is nearer to the plane than the light (w > 0; beyond the
//    light a point would project through infinity as an "anti-shadow")
uniform vec4 receiverSideMC;
uniform vec4 belowLightMC;
void main()
{
  gl_ClipDistance[0] = dot(receiverSideMC, vertexMC);
  gl_ClipDistance[1] = dot(belowLightMC, vertexMC);
  gl_Position = shadowMCDC * vertexMC;
}
