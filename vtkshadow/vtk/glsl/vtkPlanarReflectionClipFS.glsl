  // vtkPlanarReflectionPass: clip plane at the mirror, in view coordinates
  // (camera-relative, so a mirror 1e6 from the origin clips as well as one
  // at it). The fragment's view position comes from its window position and
  // depth; fragments of the mirrored scene on the eye's side of the mirror
  // (reflections of what lies behind it) are discarded.
  if (vshMirrorClipOn != 0)
  {
    vec4 vshNdc = vec4(2.0 * (gl_FragCoord.xy - vshMirrorViewport.xy) / vshMirrorViewport.zw - 1.0,
      2.0 * gl_FragCoord.z - 1.0, 1.0);
    vec4 vshVc = vshMirrorDCVC * vshNdc;
    if (dot(vshMirrorPlaneVC.xyz, vshVc.xyz / vshVc.w) + vshMirrorPlaneVC.w < 0.0)
    {
      discard;
    }
  }
