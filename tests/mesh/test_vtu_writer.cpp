// write_vtu: the file is complete, readable by VTK's own reader, and never half-written.

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "mesh/mesher.hpp"
#include "mesh/vtu_writer.hpp"
#include "pslg_fixtures.hpp"

namespace rheomag::mesh {
namespace {

std::filesystem::path scratch_dir() {
  auto dir =
      std::filesystem::temp_directory_path() / ("rheomag_vtu_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::vector<std::string> names(const Pslg& pslg) {
  std::vector<std::string> out;
  for (const auto& r : pslg.regions) out.push_back(r.name);
  return out;
}

TEST(WriteVtu, WrittenFileReadsBackWithItsFields) {
  const Pslg pslg = fixtures::valve_like_pslg();
  for (int order : {1, 2}) {
    MeshOptions options;
    options.order = order;
    const Mesh mesh = generate_mesh(pslg, options);
    const std::size_t cells = mesh.triangles.size(), points = mesh.nodes.size();
    VtuFields fields;
    std::vector<double> area(cells);
    for (std::size_t t = 0; t < cells; ++t) area[t] = fixtures::signed_area(mesh, t);
    fields.add_cell_scalar("area", area);
    fields.add_cell_vector("B", std::vector<std::array<double, 3>>(cells, {0.1, 0.2, 0.0}));
    fields.add_cell_int("material", std::vector<int>(cells, 3));
    std::vector<double> radius(points);
    for (std::size_t i = 0; i < points; ++i) radius[i] = mesh.nodes[i].r;
    fields.add_point_scalar("A", radius);
    fields.add_point_vector("grad", std::vector<std::array<double, 3>>(points, {1, 2, 3}));

    const auto path = scratch_dir() / ("valve_p" + std::to_string(order) + ".vtu");
    write_vtu(path.string(), mesh, fields, names(pslg));
    EXPECT_FALSE(std::filesystem::exists(path.string() + ".tmp"));

    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfCells(), static_cast<vtkIdType>(cells));
    ASSERT_EQ(grid->GetNumberOfPoints(), static_cast<vtkIdType>(points));
    EXPECT_EQ(grid->GetCellType(0), order == 1 ? VTK_TRIANGLE : VTK_QUADRATIC_TRIANGLE);
    double p[3];
    grid->GetPoint(static_cast<vtkIdType>(points - 1), p);
    EXPECT_EQ(p[0], mesh.nodes.back().r);
    EXPECT_EQ(p[1], mesh.nodes.back().z);
    EXPECT_EQ(p[2], 0.0);

    vtkCellData* cd = grid->GetCellData();
    for (const char* name : {"region", "area", "B", "material"})
      ASSERT_NE(cd->GetArray(name), nullptr) << name;
    EXPECT_EQ(cd->GetArray("B")->GetNumberOfComponents(), 3);
    EXPECT_EQ(cd->GetArray("region")->GetComponent(static_cast<vtkIdType>(cells - 1), 0),
              mesh.region.back());
    EXPECT_EQ(cd->GetArray("area")->GetComponent(7, 0), area[7]);
    EXPECT_EQ(cd->GetArray("material")->GetComponent(0, 0), 3.0);
    vtkPointData* pd = grid->GetPointData();
    ASSERT_NE(pd->GetArray("A"), nullptr);
    ASSERT_NE(pd->GetArray("grad"), nullptr);
    EXPECT_EQ(pd->GetArray("grad")->GetComponent(5, 2), 3.0);
    EXPECT_EQ(pd->GetArray("A")->GetComponent(11, 0), mesh.nodes[11].r);

    auto* region_names =
        vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("region_names"));
    ASSERT_NE(region_names, nullptr);
    ASSERT_EQ(region_names->GetNumberOfValues(), 5);
    EXPECT_EQ(region_names->GetValue(2), "gap");
  }
  std::filesystem::remove_all(scratch_dir());
}

TEST(WriteVtu, UnwritableDirectoryIsAnInputError) {
  MeshOptions options;
  options.order = 1;
  const Mesh mesh = generate_mesh(fixtures::valve_like_pslg(), options);
  EXPECT_THROW(write_vtu("/nonexistent_dir_rheomag/out.vtu", mesh), InputError);
  const auto dir = scratch_dir() / "read_only";
  std::filesystem::create_directories(dir);
  std::filesystem::permissions(
      dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  if (::access(dir.c_str(), W_OK) != 0) {  // root can write anywhere: only checked as a user
    EXPECT_THROW(write_vtu((dir / "out.vtu").string(), mesh), InputError);
  }
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
  std::filesystem::remove_all(scratch_dir());
}

TEST(WriteVtu, FieldOfTheWrongLengthIsRejected) {
  MeshOptions options;
  options.order = 1;
  const Mesh mesh = generate_mesh(fixtures::valve_like_pslg(), options);
  VtuFields fields;
  fields.add_cell_scalar("short", std::vector<double>(3, 0.0));
  const auto path = scratch_dir() / "bad.vtu";
  EXPECT_THROW(write_vtu(path.string(), mesh, fields), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_THROW(fields.add_point_scalar("short", {}), std::invalid_argument);  // duplicate name
  std::filesystem::remove_all(scratch_dir());
}

// A field holding NaN or inf is refused before the file is written (the non-finite guard of
// every output, core/finite_output.hpp): the old file stays.
TEST(WriteVtu, NonFiniteFieldIsRefusedAndTheOldFileKept) {
  MeshOptions options;
  options.order = 1;
  const Mesh mesh = generate_mesh(fixtures::valve_like_pslg(), options);
  const auto path = scratch_dir() / "field.vtu";
  write_vtu(path.string(), mesh);
  const auto size = std::filesystem::file_size(path);
  std::vector<double> b(mesh.triangles.size(), 0.5);
  b[7] = std::nan("");
  VtuFields fields;
  fields.add_cell_scalar("B", b);
  try {
    write_vtu(path.string(), mesh, fields);
    ADD_FAILURE() << "no error";
  } catch (const NonFiniteOutputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path.string() +
                  ": field 'B' (1 per cell): value 7 is not a finite number (nan); the result was "
                  "not written");
  }
  EXPECT_EQ(std::filesystem::file_size(path), size);
  std::filesystem::remove_all(scratch_dir());
}

}  // namespace
}  // namespace rheomag::mesh
