//VTK::System::Dec
// vtkPlanarShadowPass: one value per pair channel. Sampled area lights add
// one light sample's share (1/N in the soft pair's channel) where the
// sample's shadow covers the pixel (the stencil says where); additive
// blending sums the N samples. Translucent casters write (1 - opacity) in
// the pair's channel and 1 in the others, and multiplicative blending
// multiplies the projected triangles covering a pixel.
uniform vec4 sampleWeight;
out vec4 shadowShare;
void main()
{
  shadowShare = sampleWeight;
}
