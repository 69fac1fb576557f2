// FrameMesh -> .vtu through vtkXMLUnstructuredGridWriter (see vtu_writer.h).
#include "post/vtu_writer.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

namespace isopound::post {
namespace {

vtkNew<vtkDoubleArray> to_array(const MeshArray& a) {
  vtkNew<vtkDoubleArray> out;
  out->SetName(a.name.c_str());
  out->SetNumberOfComponents(a.components);
  out->SetNumberOfTuples(static_cast<vtkIdType>(a.values.size() / a.components));
  for (std::size_t i = 0; i < a.values.size(); ++i)
    out->SetValue(static_cast<vtkIdType>(i), a.values[i]);
  return out;
}

}  // namespace

void write_vtu(const FrameMesh& mesh, const std::string& path) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : mesh.points) points->InsertNextPoint(p[0], p[1], p[2]);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(mesh.cells.size()));
  for (const MeshCell& c : mesh.cells) {
    vtkNew<vtkIdList> ids;
    for (int i : c.points) ids->InsertNextId(i);
    grid->InsertNextCell(c.vtk_type, ids);
  }
  for (const MeshArray& a : mesh.point_data) grid->GetPointData()->AddArray(to_array(a));
  for (const MeshArray& a : mesh.cell_data) grid->GetCellData()->AddArray(to_array(a));
  // The time of the frame as field data, for readers without the .pvd.
  vtkNew<vtkDoubleArray> time;
  time->SetName("TimeValue");
  time->InsertNextValue(mesh.time);
  grid->GetFieldData()->AddArray(time);
  for (const MeshArray& a : mesh.field_data) grid->GetFieldData()->AddArray(to_array(a));

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(grid);
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw std::runtime_error("cannot write " + path);
}

}  // namespace isopound::post
