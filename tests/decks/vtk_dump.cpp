// Prints the cells of a surface file written by fix tri/vtk (.vtp or .pvtp), one line per
// triangle. Used by the deck tests.
//   tri-vtk-dump FILE               id shape type vx vy vz wx wy wz fx fy fz (particle files)
//   tri-vtk-dump FILE NAME [NAME ...]  the named cell arrays, every component, in that order;
//                                   NAME "points" gives the triangle's 9 corner coordinates
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: tri-vtk-dump FILE.vtp|FILE.pvtp [ARRAY ...]\n");
    return 2;
  }
  const std::string path = argv[1];
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
  std::vector<std::string> names;
  for (int k = 2; k < argc; ++k)
    names.push_back(argv[k]);
  const bool classic = names.empty();
  if (classic)
    names = {"id", "shape", "type", "velocity", "omega", "force"};
  vtkCellData *cd = poly->GetCellData();
  std::vector<vtkDataArray *> arrays;
  for (const std::string &name : names) {
    vtkDataArray *a = name == "points" ? nullptr : cd->GetArray(name.c_str());
    if (name != "points" && !a) {
      std::fprintf(stderr, "%s: no cell array '%s'\n", path.c_str(), name.c_str());
      return 1;
    }
    arrays.push_back(a);
  }
  std::printf("# %lld cells\n", static_cast<long long>(poly->GetNumberOfCells()));
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c) {
    if (classic) {
      std::printf("%lld %lld %lld", static_cast<long long>(arrays[0]->GetComponent(c, 0)),
                  static_cast<long long>(arrays[1]->GetComponent(c, 0)),
                  static_cast<long long>(arrays[2]->GetComponent(c, 0)));
      for (int k = 3; k < 6; ++k)
        for (int j = 0; j < 3; ++j)
          std::printf(" %.17g", arrays[k]->GetComponent(c, j));
      std::printf("\n");
      continue;
    }
    const char *sep = "";
    for (vtkDataArray *a : arrays) {
      if (!a) {
        vtkCell *cell = poly->GetCell(c);
        for (vtkIdType k = 0; k < cell->GetNumberOfPoints(); ++k) {
          double x[3];
          poly->GetPoint(cell->GetPointId(k), x);
          std::printf("%s%.17g %.17g %.17g", sep, x[0], x[1], x[2]);
          sep = " ";
        }
        continue;
      }
      for (int j = 0; j < a->GetNumberOfComponents(); ++j) {
        std::printf("%s%.17g", sep, a->GetComponent(c, j));
        sep = " ";
      }
    }
    std::printf("\n");
  }
  return 0;
}
