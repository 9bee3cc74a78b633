// Mesh and fields to a VTK XML unstructured grid (see vtu_writer.hpp).

#include "mesh/vtu_writer.hpp"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace rheomag::mesh {

namespace {

std::vector<double> flatten(const std::vector<std::array<double, 3>>& values) {
  std::vector<double> flat;
  flat.reserve(3 * values.size());
  for (const auto& v : values) flat.insert(flat.end(), v.begin(), v.end());
  return flat;
}

vtkSmartPointer<vtkDataArray> to_vtk(const VtuFields::Field& field) {
  vtkSmartPointer<vtkDataArray> array;
  if (field.integer)
    array = vtkSmartPointer<vtkIntArray>::New();
  else
    array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(field.name.c_str());
  array->SetNumberOfComponents(field.components);
  const vtkIdType tuples = static_cast<vtkIdType>(field.values.size()) / field.components;
  array->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < tuples; ++i)
    for (int c = 0; c < field.components; ++c)
      array->SetComponent(i, c, field.values[static_cast<std::size_t>(i * field.components + c)]);
  return array;
}

vtkNew<vtkUnstructuredGrid> make_grid(const Mesh& mesh) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.nodes.size()));
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.nodes[i].r, mesh.nodes[i].z, 0.0);
  grid->SetPoints(points);
  const int per_cell = mesh.nodes_per_triangle();
  const int cell_type = mesh.order == 2 ? VTK_QUADRATIC_TRIANGLE : VTK_TRIANGLE;
  grid->Allocate(static_cast<vtkIdType>(mesh.triangles.size()));
  vtkIdType ids[6];
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < per_cell; ++k) ids[k] = t[static_cast<std::size_t>(k)];
    grid->InsertNextCell(cell_type, per_cell, ids);
  }
  return grid;
}

}  // namespace

void VtuFields::add(Field field) {
  for (const Field& f : fields_)
    if (f.name == field.name)
      throw std::invalid_argument("write_vtu: field '" + field.name + "' added twice");
  fields_.push_back(std::move(field));
}

void VtuFields::add_cell_scalar(std::string name, std::vector<double> values) {
  add({std::move(name), Location::cell, 1, false, std::move(values)});
}

void VtuFields::add_cell_vector(std::string name,
                                const std::vector<std::array<double, 3>>& values) {
  add({std::move(name), Location::cell, 3, false, flatten(values)});
}

void VtuFields::add_cell_int(std::string name, const std::vector<int>& values) {
  add({std::move(name), Location::cell, 1, true,
       std::vector<double>(values.begin(), values.end())});
}

void VtuFields::add_point_scalar(std::string name, std::vector<double> values) {
  add({std::move(name), Location::point, 1, false, std::move(values)});
}

void VtuFields::add_point_vector(std::string name,
                                 const std::vector<std::array<double, 3>>& values) {
  add({std::move(name), Location::point, 3, false, flatten(values)});
}

void write_vtu(const std::string& path, const Mesh& mesh, const VtuFields& fields,
               const std::vector<std::string>& region_names) {
  vtkNew<vtkUnstructuredGrid> grid = make_grid(mesh);

  vtkNew<vtkIntArray> region;
  region->SetName("region");
  region->SetNumberOfTuples(static_cast<vtkIdType>(mesh.region.size()));
  for (std::size_t i = 0; i < mesh.region.size(); ++i)
    region->SetValue(static_cast<vtkIdType>(i), mesh.region[i]);
  if (mesh.region.size() == mesh.triangles.size()) grid->GetCellData()->AddArray(region);

  for (const VtuFields::Field& field : fields.fields()) {
    const bool on_cells = field.location == VtuFields::Location::cell;
    const std::size_t expected = static_cast<std::size_t>(field.components) *
                                 (on_cells ? mesh.triangles.size() : mesh.nodes.size());
    if (field.values.size() != expected)
      throw std::invalid_argument(
          "write_vtu: field '" + field.name + "' has " + std::to_string(field.values.size()) +
          " values; expected " + std::to_string(expected) + " (" +
          std::to_string(field.components) + " per " + (on_cells ? "triangle" : "node") + ")");
    if (field.name == "region")
      throw std::invalid_argument("write_vtu: the field name 'region' is reserved");
    auto array = to_vtk(field);
    if (on_cells)
      grid->GetCellData()->AddArray(array);
    else
      grid->GetPointData()->AddArray(array);
  }

  vtkNew<vtkStringArray> names;
  names->SetName("region_names");
  for (const std::string& name : region_names) names->InsertNextValue(name);
  grid->GetFieldData()->AddArray(names);

  // PATH is either the old file or the complete new one; VTK's status is checked.
  write_file_atomically_with(path, [&](const std::filesystem::path& temporary) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(temporary.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    return writer->Write() == 1 && writer->GetErrorCode() == 0;
  });
}

}  // namespace rheomag::mesh
