//VTK::System::Dec
// vtkPlanarShadowPass: mark the pixels a projected caster covers. Each
// (receiver, light) pair owns one bit of an RGBA32UI mask; the pass ORs the
// bits with glLogicOp, so overlapping casters never darken twice.
uniform uvec4 pairBit;
out uvec4 maskBits;
void main()
{
  maskBits = pairBit;
}
