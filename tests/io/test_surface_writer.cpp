// Tests of surface_writer.h: what ParaView will read back through VTK's own XML readers.
#include "surface_writer.h"

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;

// A fresh, empty directory per test under the system temporary directory.
fs::path scratch_dir() {
  const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::temp_directory_path() / (std::string("tri_surface_writer_") + info->name());
  fs::remove_all(dir);
  return dir;
}

// A particle of `ntri` triangles, corner k of triangle t at (offset + t, k, 10 * id).
tri::TriangleSoA particle(int ntri, double offset, double id) {
  tri::TriangleSoA soa;
  soa.resize(ntri);
  for (int t = 0; t < ntri; ++t)
    for (int k = 0; k < 3; ++k)
      soa.set_vertex(t, k, Eigen::Vector3d(offset + t, k, 10.0 * id));
  return soa;
}

// Particle p (0-based) has id 100 + p, shape p, type p + 1, v = (p, 1, 2), w = (3, p, 4),
// f = (5, 6, p), torque (7, p, -8), orientation (0.5, -0.5, 0.5, p / 10) and p + 4 triangles.
tri::ParticleValues values_of(int p) {
  tri::ParticleValues v;
  v.id = 100 + p;
  v.shape = p;
  v.type = p + 1;
  const double vel[3] = {double(p), 1, 2}, w[3] = {3, double(p), 4}, f[3] = {5, 6, double(p)};
  const double t[3] = {7, double(p), -8}, q[4] = {0.5, -0.5, 0.5, p / 10.0};
  std::copy(vel, vel + 3, v.velocity);
  std::copy(w, w + 3, v.omega);
  std::copy(f, f + 3, v.force);
  std::copy(t, t + 3, v.torque);
  std::copy(q, q + 4, v.orientation);
  return v;
}

void add_particle(tri::SurfaceCells &cells, int p) {
  cells.append_particle(particle(p + 4, 0.5 * p, 100 + p), values_of(p));
}

vtkDataArray *cell_array(vtkPolyData *poly, const char *name) {
  vtkDataArray *a = poly->GetCellData()->GetArray(name);
  EXPECT_NE(a, nullptr) << "missing cell array " << name;
  return a;
}

// Checks the cells read back against particles first..first+count-1 written in that order.
void expect_particles(vtkPolyData *poly, int first, int count) {
  int cell = 0;
  for (int p = first; p < first + count; ++p) {
    for (int t = 0; t < p + 4; ++t, ++cell) {
      ASSERT_LT(cell, poly->GetNumberOfCells());
      vtkCell *c = poly->GetCell(cell);
      ASSERT_EQ(c->GetCellType(), VTK_TRIANGLE);
      for (int k = 0; k < 3; ++k) {
        double x[3];
        poly->GetPoint(c->GetPointId(k), x);
        EXPECT_EQ(x[0], 0.5 * p + t);
        EXPECT_EQ(x[1], k);
        EXPECT_EQ(x[2], 10.0 * (100 + p));
      }
      EXPECT_EQ(cell_array(poly, "id")->GetComponent(cell, 0), 100 + p);
      EXPECT_EQ(cell_array(poly, "shape")->GetComponent(cell, 0), p);
      EXPECT_EQ(cell_array(poly, "type")->GetComponent(cell, 0), p + 1);
      const tri::ParticleValues v = values_of(p);
      for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(cell_array(poly, "velocity")->GetComponent(cell, d), v.velocity[d]);
        EXPECT_EQ(cell_array(poly, "omega")->GetComponent(cell, d), v.omega[d]);
        EXPECT_EQ(cell_array(poly, "force")->GetComponent(cell, d), v.force[d]);
        EXPECT_EQ(cell_array(poly, "torque")->GetComponent(cell, d), v.torque[d]);
      }
      for (int d = 0; d < 4; ++d)
        EXPECT_EQ(cell_array(poly, "orientation")->GetComponent(cell, d), v.orientation[d]);
    }
  }
  EXPECT_EQ(cell, poly->GetNumberOfCells());
}

std::string slurp(const fs::path &p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SurfaceWriter, SurfaceCellsAppendAndClear) {
  tri::SurfaceCells cells;
  add_particle(cells, 0);
  add_particle(cells, 1);
  EXPECT_EQ(cells.num_triangles(), 4 + 5);
  EXPECT_EQ(cells.xyz.size(), 9u * 9u);
  EXPECT_EQ(cells.force.size(), 3u * 9u);
  EXPECT_EQ(cells.torque.size(), 3u * 9u);
  EXPECT_EQ(cells.orientation.size(), 4u * 9u);
  EXPECT_EQ(cells.orientation[4 * 4 + 3], 0.1); // particle 1, triangle 0: q.z = 1 / 10
  EXPECT_EQ(cells.xyz[9 * 4 + 3 * 2 + 1], 2.0); // particle 1, triangle 0, corner 2, y
  cells.clear();
  EXPECT_EQ(cells.num_triangles(), 0);
  EXPECT_TRUE(cells.xyz.empty() && cells.velocity.empty() && cells.type.empty() &&
              cells.torque.empty() && cells.orientation.empty());
}

TEST(SurfaceWriter, VtpRoundTripsTwoParticles) {
  const fs::path dir = scratch_dir();
  tri::SurfaceCells cells;
  add_particle(cells, 0);
  add_particle(cells, 1);
  const fs::path file = dir / "post" / "deeper" / "frame_0.vtp"; // parents do not exist yet
  tri::write_vtp(file.string(), cells);

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkPolyData *poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfCells(), 4 + 5);
  EXPECT_EQ(poly->GetNumberOfPoints(), 3 * (4 + 5));
  EXPECT_EQ(cell_array(poly, "velocity")->GetNumberOfComponents(), 3);
  EXPECT_EQ(cell_array(poly, "torque")->GetNumberOfComponents(), 3);
  EXPECT_EQ(cell_array(poly, "orientation")->GetNumberOfComponents(), 4);
  expect_particles(poly, 0, 2);

  // Binary, zlib-compressed, appended (ParaView's fastest path), not ASCII or base64.
  const std::string text = slurp(file);
  EXPECT_NE(text.find("vtkZLibDataCompressor"), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_EQ(text.find("format=\"ascii\""), std::string::npos);
  fs::remove_all(dir);
}

TEST(SurfaceWriter, EmptyPieceIsValid) {
  const fs::path dir = scratch_dir();
  const fs::path file = dir / "empty.vtp";
  tri::write_vtp(file.string(), tri::SurfaceCells{});
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_NE(reader->GetOutput()->GetCellData()->GetArray("force"), nullptr);
  fs::remove_all(dir);
}

TEST(SurfaceWriter, PvtpJoinsPiecesOfTwoRanks) {
  const fs::path dir = scratch_dir();
  tri::SurfaceCells rank0, rank1;
  add_particle(rank0, 0);
  add_particle(rank1, 1);
  add_particle(rank1, 2);
  // Pieces in a subdirectory, named relative to the .pvtp, as the fix will lay them out.
  tri::write_vtp((dir / "frame_7" / "rank_0.vtp").string(), rank0);
  tri::write_vtp((dir / "frame_7" / "rank_1.vtp").string(), rank1);
  const fs::path summary = dir / "frame_7.pvtp";
  tri::write_pvtp(summary.string(), {"frame_7/rank_0.vtp", "frame_7/rank_1.vtp"}, rank0);

  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(summary.string().c_str());
  reader->Update();
  ASSERT_EQ(reader->GetNumberOfPieces(), 2);
  vtkPolyData *poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfCells(), 4 + 5 + 6);
  EXPECT_NE(slurp(summary).find("Name=\"orientation\" NumberOfComponents=\"4\""),
            std::string::npos);
  expect_particles(poly, 0, 3); // pieces in order: rank 0's particle 0, rank 1's 1 and 2
  std::set<double> ids;
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
    ids.insert(cell_array(poly, "id")->GetComponent(c, 0));
  EXPECT_EQ(ids, (std::set<double>{100, 101, 102}));
  fs::remove_all(dir);
}

TEST(SurfaceWriter, PvdListsFramesAndIsRewritten) {
  const fs::path dir = scratch_dir();
  const fs::path pvd = dir / "particles.pvd";
  tri::write_pvd(pvd.string(), {{0.0, "p_0.pvtp"}, {1e-5, "p_1000.pvtp"}});
  const std::vector<std::pair<double, std::string>> frames = {
      {0.0, "p_0.pvtp"}, {1e-5, "p_1000.pvtp"}, {2.0000000000000002e-5, "p & <2000>.pvtp"}};
  tri::write_pvd(pvd.string(), frames); // rewrites: a run appends a frame each output step
  EXPECT_FALSE(fs::exists(pvd.string() + ".tmp"));

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.string().c_str());
  ASSERT_EQ(parser->Parse(), 1) << "not well-formed XML";
  vtkXMLDataElement *root = parser->GetRootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement *collection = root->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 3);
  for (int i = 0; i < 3; ++i) {
    vtkXMLDataElement *e = collection->GetNestedElement(i);
    EXPECT_STREQ(e->GetName(), "DataSet");
    double t = -1.0;
    ASSERT_TRUE(e->GetScalarAttribute("timestep", t));
    EXPECT_EQ(t, frames[i].first); // 17 digits: the double comes back exactly
    EXPECT_EQ(std::string(e->GetAttribute("file")), frames[i].second);
  }
  fs::remove_all(dir);
}

TEST(SurfaceWriter, FailuresNameThePath) {
  const fs::path dir = scratch_dir();
  fs::create_directories(dir);
  std::ofstream(dir / "plain_file") << "x";
  // A directory cannot be created under a regular file.
  const std::string bad = (dir / "plain_file" / "sub" / "a.vtp").string();
  try {
    tri::write_vtp(bad, tri::SurfaceCells{});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
  EXPECT_THROW(tri::write_pvd((dir / "plain_file" / "x.pvd").string(), {}), std::runtime_error);
  // Arrays of inconsistent length are refused, not written as nonsense.
  tri::SurfaceCells broken;
  add_particle(broken, 0);
  broken.force.pop_back();
  const std::string ok_path = (dir / "broken.vtp").string();
  try {
    tri::write_vtp(ok_path, broken);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find(ok_path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(ok_path));
  tri::SurfaceCells no_torque;
  add_particle(no_torque, 0);
  no_torque.orientation.pop_back();
  EXPECT_THROW(tri::write_vtp(ok_path, no_torque), std::runtime_error);
  tri::WallCells wall;
  const double corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0}, v[3] = {0, 0, 0};
  wall.append_triangle(1, corners, v);
  wall.velocity.pop_back();
  const std::string wall_path = (dir / "wall.vtp").string();
  try {
    tri::write_wall_vtp(wall_path, wall);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find(wall_path), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(wall_path));
  fs::remove_all(dir);
}

// A wall mesh: triangle t has id 10 + 3t (ids need not be contiguous), corners
// (t, 0, 0), (t + 1, 0, 0), (t, 1, 2t) and velocity (t, -t, 0.5).
TEST(SurfaceWriter, WallVtpRoundTrips) {
  const fs::path dir = scratch_dir();
  tri::WallCells wall;
  for (int t = 0; t < 3; ++t) {
    const double c[9] = {double(t), 0, 0, t + 1.0, 0, 0, double(t), 1, 2.0 * t};
    const double v[3] = {double(t), -double(t), 0.5};
    wall.append_triangle(10 + 3 * t, c, v);
  }
  EXPECT_EQ(wall.num_triangles(), 3);
  const fs::path file = dir / "post" / "p_walls_cad_100.vtp";
  tri::write_wall_vtp(file.string(), wall);

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkPolyData *poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfCells(), 3);
  for (int t = 0; t < 3; ++t) {
    vtkCell *c = poly->GetCell(t);
    ASSERT_EQ(c->GetCellType(), VTK_TRIANGLE);
    const double expected[3][3] = {{double(t), 0, 0}, {t + 1.0, 0, 0}, {double(t), 1, 2.0 * t}};
    for (int k = 0; k < 3; ++k) {
      double x[3];
      poly->GetPoint(c->GetPointId(k), x);
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(x[d], expected[k][d]);
    }
    EXPECT_EQ(cell_array(poly, "id")->GetComponent(t, 0), 10 + 3 * t);
    EXPECT_EQ(cell_array(poly, "velocity")->GetComponent(t, 0), t);
    EXPECT_EQ(cell_array(poly, "velocity")->GetComponent(t, 1), -t);
    EXPECT_EQ(cell_array(poly, "velocity")->GetComponent(t, 2), 0.5);
  }
  EXPECT_EQ(poly->GetCellData()->GetArray("shape"), nullptr); // walls carry no particle arrays
  wall.clear();
  EXPECT_EQ(wall.num_triangles(), 0);
  EXPECT_TRUE(wall.xyz.empty() && wall.velocity.empty());
  tri::write_wall_vtp((dir / "empty_wall.vtp").string(), wall); // an empty mesh is valid
  fs::remove_all(dir);
}

TEST(SurfaceWriter, PvdPartsAndNames) {
  const fs::path dir = scratch_dir();
  const fs::path pvd = dir / "p_walls.pvd";
  const std::vector<tri::PvdEntry> entries = {{0.0, "p_walls_cad_0.vtp", 0, "cad"},
                                              {0.0, "p_walls_lid_0.vtp", 1, "lid"},
                                              {1e-3, "p_walls_cad_100.vtp", 0, "cad"},
                                              {1e-3, "p_walls_lid_100.vtp", 1, "lid"}};
  tri::write_pvd_parts(pvd.string(), entries);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.string().c_str());
  ASSERT_EQ(parser->Parse(), 1) << "not well-formed XML";
  vtkXMLDataElement *collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
  ASSERT_NE(collection, nullptr);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 4);
  for (int i = 0; i < 4; ++i) {
    vtkXMLDataElement *e = collection->GetNestedElement(i);
    int part = -1;
    double t = -1.0;
    ASSERT_TRUE(e->GetScalarAttribute("part", part));
    ASSERT_TRUE(e->GetScalarAttribute("timestep", t));
    EXPECT_EQ(part, entries[i].part);
    EXPECT_EQ(t, entries[i].time);
    EXPECT_EQ(std::string(e->GetAttribute("name")), entries[i].name);
    EXPECT_EQ(std::string(e->GetAttribute("file")), entries[i].file);
  }
  // The particles' .pvd (no names) keeps one part and no name attribute.
  tri::write_pvd(pvd.string(), {{0.0, "p_0.vtp"}});
  EXPECT_EQ(slurp(pvd).find("name="), std::string::npos);
  EXPECT_NE(slurp(pvd).find("part=\"0\""), std::string::npos);
  fs::remove_all(dir);
}

} // namespace
