//VTK::System::Dec
// vtkPlanarShadowPass, sampled area lights: add one light sample's share
// (1/N in the soft pair's channel) where the sample's shadow covers the
// pixel (the stencil says where); additive blending sums the N samples.
uniform vec4 sampleWeight;
out vec4 shadowShare;
void main()
{
  shadowShare = sampleWeight;
}
