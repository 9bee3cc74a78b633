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
#include "core/finite_output.hpp"

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

vtkNew<vtkUnstructuredGrid> make_grid(const VtuGrid& in) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(in.points.size()));
  for (std::size_t i = 0; i < in.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), in.points[i].data());
  grid->SetPoints(points);
  grid->Allocate(static_cast<vtkIdType>(in.cells()));
  std::vector<vtkIdType> ids(static_cast<std::size_t>(in.nodes_per_cell));
  for (std::size_t c = 0; c < in.cells(); ++c) {
    for (int k = 0; k < in.nodes_per_cell; ++k)
      ids[static_cast<std::size_t>(k)] =
          in.connectivity[c * static_cast<std::size_t>(in.nodes_per_cell) +
                          static_cast<std::size_t>(k)];
    grid->InsertNextCell(in.cell_type, in.nodes_per_cell, ids.data());
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
  VtuGrid grid;
  grid.points.reserve(mesh.nodes.size());
  for (const Point& p : mesh.nodes) grid.points.push_back({p.r, p.z, 0.0});
  grid.nodes_per_cell = mesh.nodes_per_triangle();
  grid.cell_type = mesh.order == 2 ? VTK_QUADRATIC_TRIANGLE : VTK_TRIANGLE;
  for (const auto& t : mesh.triangles)
    grid.connectivity.insert(grid.connectivity.end(), t.begin(), t.begin() + grid.nodes_per_cell);
  grid.region = mesh.region;
  write_vtu(path, grid, fields, region_names);
}

void write_vtu(const std::string& path, const VtuGrid& in, const VtuFields& fields,
               const std::vector<std::string>& region_names) {
  vtkNew<vtkUnstructuredGrid> grid = make_grid(in);

  vtkNew<vtkIntArray> region;
  region->SetName("region");
  region->SetNumberOfTuples(static_cast<vtkIdType>(in.region.size()));
  for (std::size_t i = 0; i < in.region.size(); ++i)
    region->SetValue(static_cast<vtkIdType>(i), in.region[i]);
  if (in.region.size() == in.cells()) grid->GetCellData()->AddArray(region);

  for (const VtuFields::Field& field : fields.fields()) {
    const bool on_cells = field.location == VtuFields::Location::cell;
    const std::size_t expected =
        static_cast<std::size_t>(field.components) * (on_cells ? in.cells() : in.points.size());
    if (field.values.size() != expected)
      throw std::invalid_argument(
          "write_vtu: field '" + field.name + "' has " + std::to_string(field.values.size()) +
          " values; expected " + std::to_string(expected) + " (" +
          std::to_string(field.components) + " per " + (on_cells ? "cell" : "node") + ")");
    if (field.name == "region")
      throw std::invalid_argument("write_vtu: the field name 'region' is reserved");
    require_finite_values(field.values, path,
                          "field '" + field.name + "' (" + std::to_string(field.components) +
                              " per " + (on_cells ? "cell" : "node") + "):");
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
