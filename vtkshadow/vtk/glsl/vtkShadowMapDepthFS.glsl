//VTK::System::Dec
// vtkCascadedShadowMapPass: depth only.
void main()
{
}
