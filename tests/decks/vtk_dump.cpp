// Prints the cells of a particle-surface file written by fix tri/vtk (.vtp or .pvtp), one
// line per triangle: id shape type vx vy vz wx wy wz fx fy fz. Used by the deck tests.
// With --points first, the triangles' corners instead: id x0 y0 z0 x1 y1 z1 x2 y2 z2.
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <cstdio>
#include <string>

int main(int argc, char **argv) {
  const bool points = argc == 3 && std::string(argv[1]) == "--points";
  if (argc != 2 && !points) {
    std::fprintf(stderr, "usage: tri-vtk-dump [--points] FILE.vtp|FILE.pvtp\n");
    return 2;
  }
  const std::string path = argv[argc - 1];
  vtkSmartPointer<vtkPolyData> poly;
  if (path.size() > 5 && path.substr(path.size() - 5) == ".pvtp") {
    auto reader = vtkSmartPointer<vtkXMLPPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    poly = reader->GetOutput();
  } else {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    poly = reader->GetOutput();
  }
  vtkCellData *cd = poly->GetCellData();
  const char *names[] = {"id", "shape", "type", "velocity", "omega", "force"};
  vtkDataArray *arrays[6];
  for (int k = 0; k < 6; ++k) {
    arrays[k] = cd->GetArray(names[k]);
    if (!arrays[k]) {
      std::fprintf(stderr, "%s: no cell array '%s'\n", path.c_str(), names[k]);
      return 1;
    }
  }
  std::printf("# %lld cells\n", static_cast<long long>(poly->GetNumberOfCells()));
  if (points) {
    for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
      std::printf("%lld", static_cast<long long>(arrays[0]->GetComponent(c, 0)));
      vtkCell *cell = poly->GetCell(c);
      for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
        double p[3];
        poly->GetPoint(cell->GetPointId(k), p);
        std::printf(" %.17g %.17g %.17g", p[0], p[1], p[2]);
      }
      std::printf("\n");
    }
    return 0;
  }
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    std::printf("%lld %lld %lld", static_cast<long long>(arrays[0]->GetComponent(c, 0)),
                static_cast<long long>(arrays[1]->GetComponent(c, 0)),
                static_cast<long long>(arrays[2]->GetComponent(c, 0)));
    for (int k = 3; k < 6; ++k)
      for (int j = 0; j < 3; ++j)
        std::printf(" %.17g", arrays[k]->GetComponent(c, j));
    std::printf("\n");
  }
  return 0;
}
