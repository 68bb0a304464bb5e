// tri-stats-columns: prints the columns of compute tri/stats, one a line, tab-separated:
//   index  name  unit  meaning
// index is 1-based, as in c_ID[index]. From the one statistics table (interaction_tally.h),
// for scripts and tests that address columns by name, and for the manual's table
// (src_plugin/doc/compute_tri_stats.md):
//   tri-stats-columns            the table
//   tri-stats-columns --markdown the manual's table rows
#include "interaction/interaction_tally.h"

#include <cstdio>
#include <cstring>

int main(int argc, char **argv) {
  const bool markdown = argc > 1 && std::strcmp(argv[1], "--markdown") == 0;
  if (argc > 2 || (argc == 2 && !markdown)) {
    std::fprintf(stderr, "usage: tri-stats-columns [--markdown]\n");
    return 2;
  }
  const auto &columns = tri::stats_columns();
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const tri::StatColumn &c = columns[k];
    if (markdown)
      std::printf("| %zu | `%s` | %s | %s |\n", k + 1, c.name.c_str(), c.unit.c_str(),
                  c.meaning.c_str());
    else
      std::printf("%zu\t%s\t%s\t%s\n", k + 1, c.name.c_str(), c.unit.c_str(), c.meaning.c_str());
  }
  return 0;
}
