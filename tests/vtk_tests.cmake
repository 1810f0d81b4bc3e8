# tests that need VTK
