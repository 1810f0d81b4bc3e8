//VTK::System::Dec
// vtkCascadedShadowMapPass: a translucent caster into a transmittance map.
// The draw blends multiplicatively (destination x source), so every
// crossing of a surface of opacity a multiplies the texel by (1 - a): the
// two crossings of a closed mesh (culling is off) give (1 - a)^2.
uniform float vshCrossing; // 1 - the caster's opacity
out vec4 vshTransmitted;
void main()
{
  vshTransmitted = vec4(vshCrossing);
}
