// tri-style-matrix: every style of Debian's LIGGGHTS and what it does beside fix tri/particles,
// from the one table (src_plugin/liggghts/style_matrix.h):
//   tri-style-matrix             one style a line, tab-separated: kind style class note instead
//   tri-style-matrix --markdown  the matrix of src_plugin/doc/from_spheres.md: per kind, the
//                                styles that work as with spheres in one row, one row per
//                                style with a meaning or refused, the irrelevant ones in one
//                                row per model
#include "style_matrix.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using tri_liggghts::StyleClass;
using tri_liggghts::StyleKind;
using tri_liggghts::StyleRow;

// A table cell: '|' would end it.
std::string cell(const char *text) {
  std::string s;
  for (const char *c = text; *c; ++c)
    s += *c == '|' ? std::string("\\|") : std::string(1, *c);
  return s;
}

std::string code_list(const std::vector<const StyleRow *> &rows) {
  std::string s;
  for (const StyleRow *r : rows)
    s += (s.empty() ? "`" : ", `") + std::string(r->style) + "`";
  return s;
}

void print_kind(StyleKind kind) {
  const char *name = tri_liggghts::kind_name(kind);
  std::vector<const StyleRow *> plain;
  std::vector<std::string> notes; // irrelevant rows, grouped by their note in table order
  for (const StyleRow &r : tri_liggghts::style_matrix()) {
    if (r.kind != kind)
      continue;
    if (r.cls == StyleClass::works && !*r.note)
      plain.push_back(&r);
    if (r.cls == StyleClass::irrelevant) {
      bool seen = false;
      for (const std::string &n : notes)
        seen = seen || n == r.note;
      if (!seen)
        notes.push_back(r.note);
    }
  }
  if (!plain.empty())
    std::printf("| %s | %s | works as with spheres |\n", name, code_list(plain).c_str());
  for (const StyleRow &r : tri_liggghts::style_matrix()) {
    if (r.kind != kind)
      continue;
    if (r.cls == StyleClass::works && *r.note)
      std::printf("| %s | `%s` | works as with spheres: %s |\n", name, r.style,
                  cell(r.note).c_str());
    else if (r.cls == StyleClass::meaning)
      std::printf("| %s | `%s` | runs: %s |\n", name, r.style, cell(r.note).c_str());
    else if (r.cls == StyleClass::refused)
      std::printf("| %s | `%s` | **ERROR**: %s; instead: %s |\n", name, r.style,
                  cell(r.note).c_str(), cell(r.instead).c_str());
  }
  for (const std::string &note : notes) {
    std::vector<const StyleRow *> group;
    for (const StyleRow &r : tri_liggghts::style_matrix())
      if (r.kind == kind && r.cls == StyleClass::irrelevant && note == r.note)
        group.push_back(&r);
    std::printf("| %s | %s | not for mesh particles: %s |\n", name, code_list(group).c_str(),
                cell(note.c_str()).c_str());
  }
}

} // namespace

int main(int argc, char **argv) {
  const bool markdown = argc > 1 && std::strcmp(argv[1], "--markdown") == 0;
  if (argc > 2 || (argc == 2 && !markdown)) {
    std::fprintf(stderr, "usage: tri-style-matrix [--markdown]\n");
    return 2;
  }
  if (!markdown) {
    for (const StyleRow &r : tri_liggghts::style_matrix())
      std::printf("%s\t%s\t%s\t%s\t%s\n", tri_liggghts::kind_name(r.kind), r.style,
                  tri_liggghts::class_name(r.cls), r.note, r.instead);
    return 0;
  }
  std::printf("| kind | style | beside fix tri/particles |\n| --- | --- | --- |\n");
  for (int k = 0; k <= static_cast<int>(StyleKind::command); ++k)
    print_kind(static_cast<StyleKind>(k));
  return 0;
}
