"""Grayscale PNG I/O for the Python tests, through VTK's own PNG reader and
writer, as numpy arrays with row 0 at the top (VTK images keep row 0 at the
bottom, PNG files at the top)."""
import numpy as np
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.util import numpy_support


def read_png(path, components=False):
    """(H, W) array, or (H, W, C) with components=True; also the VTK type name."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    a = numpy_support.vtk_to_numpy(scalars)
    a = a.reshape(h, w, -1) if components else a.reshape(h, w)
    if components:
        return a[::-1], scalars.GetDataTypeAsString()
    return a[::-1]


def write_png(path, array, bits):
    """Write an (H, W) array as 8- or 16-bit grayscale."""
    h, w = array.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    dtype = np.uint16 if bits == 16 else np.uint8
    flat = np.ascontiguousarray(array[::-1].astype(dtype)).reshape(-1)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(flat, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
