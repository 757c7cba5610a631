"""Reads a written cloud for the integration tests' checks (VTK's XML reader)."""
import vtk


def read_cloud(path, names):
    """The particles of the .vtp file at path (or of a parallel run's .pvtp and its pieces) by
    their `id`: {id: {"x": position, name: value}} for each field in names (a vector field's
    value a tuple)."""
    reader = vtk.vtkXMLPPolyDataReader() if str(path).endswith(".pvtp") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    out = reader.GetOutput()
    data = out.GetPointData()
    ids = data.GetArray("id")
    arrays = {name: data.GetArray(name) for name in names}
    def value(array, i):  # a scalar, or a vector field's tuple
        return array.GetTuple1(i) if array.GetNumberOfComponents() == 1 else array.GetTuple(i)
    return {int(ids.GetTuple1(i)): dict(x=out.GetPoint(i), **{name: value(array, i)
                                                              for name, array in arrays.items()})
            for i in range(out.GetNumberOfPoints())}
