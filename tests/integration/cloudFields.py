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


def cloud_totals(path):
    """The particle count, the summed `mass` and the cloud's attributes (its field data, e.g.
    spilledMass) of the .vtp (or .pvtp) at path: (count, mass, {name: value})."""
    reader = vtk.vtkXMLPPolyDataReader() if str(path).endswith(".pvtp") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    out = reader.GetOutput()
    mass = out.GetPointData().GetArray("mass")
    count = out.GetNumberOfPoints()
    field = out.GetFieldData()
    attributes = {field.GetArrayName(k): field.GetArray(k).GetTuple1(0)
                  for k in range(field.GetNumberOfArrays())}
    return count, sum(mass.GetTuple1(i) for i in range(count)), attributes
