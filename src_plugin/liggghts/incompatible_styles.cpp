// The styles refused next to fix tri/particles; see incompatible_styles.h. The refused styles,
// why and what instead, are rows of the compatibility matrix (style_matrix.cpp).
#include "incompatible_styles.h"
#include "style_matrix.h"

#include "compute.h"
#include "dump.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "output.h"
#include "pair.h"
#include "pair_hybrid.h"
#include "update.h"

#include <cstring>

namespace tri_liggghts {
namespace {

// Why the integrators cannot work, once: orientation and angular momentum of a triangulated
// particle are fix tri/particles' per-atom state, which only fix tri/nve advances.
const char *kTwice = " (and next to fix tri/nve the particles would move twice)";

const StyleRow *refused(StyleKind kind, const char *style) {
  const StyleRow *row = find_style(kind, style);
  return row && row->cls == StyleClass::refused ? row : nullptr;
}

// The replacement as the row gives it, with f_ID (the fix tri/particles' columns) named.
std::string instead(const StyleRow &row, const std::string &particles_id) {
  std::string use = row.instead;
  const std::string name = "f_" + particles_id;
  for (std::size_t at = 0; (at = use.find("f_ID", at)) != std::string::npos; at += name.size())
    use.replace(at, 4, name);
  return use;
}

std::string message(const std::string &what, const std::string &why, const std::string &use) {
  return "Fix tri/particles: " + what + " cannot work with triangulated particles: " + why +
         "; instead use " + use;
}

std::string fix_message(LAMMPS_NS::Fix *fix, const std::string &particles_id) {
  const std::string what = std::string("fix ") + fix->style + " (ID " + fix->id + ")";
  if (const StyleRow *row = refused(StyleKind::fix, fix->style)) {
    std::string why = row->note;
    if (fix->time_integrate)
      why += kTwice;
    return message(what, why, instead(*row, particles_id));
  }
  if (fix->time_integrate && std::strcmp(fix->style, "tri/nve") != 0)
    return message(what,
                   "it integrates the atoms' motion, which for triangulated particles fix "
                   "tri/nve alone does (it also turns their orientation)",
                   "fix tri/nve");
  return "";
}

std::string compute_message(LAMMPS_NS::Compute *compute, const std::string &particles_id) {
  const StyleRow *row = refused(StyleKind::compute, compute->style);
  if (!row)
    return "";
  const std::string what = std::string("compute ") + compute->style + " (ID " + compute->id + ")";
  return message(what, row->note, instead(*row, particles_id));
}

std::string pair_message(LAMMPS_NS::LAMMPS *lmp) {
  LAMMPS_NS::Force *force = lmp->force;
  if (!force->pair || !force->pair_style)
    return "";
  const std::string style = force->pair_style;
  if (style == "tri/gran")
    return "";
  const std::string what = "pair_style " + style;
  if (auto *hybrid = dynamic_cast<LAMMPS_NS::PairHybrid *>(force->pair)) {
    std::string subs;
    for (int k = 0; k < hybrid->nstyles; ++k)
      subs += std::string(k ? ", " : "") + hybrid->keywords[k];
    return message(what + " (sub-styles " + subs + ")",
                   "the contacts of triangulated particles, their checks and statistics come "
                   "from pair tri/gran as the one pair style",
                   "pair_style tri/gran alone");
  }
  if (const StyleRow *row = refused(StyleKind::pair_style, style.c_str()))
    return message(what, row->note, row->instead);
  return message(what, "it does not compute contacts of triangulated particles",
                 find_style(StyleKind::pair_style, "gran")->instead);
}

} // namespace

std::string incompatible_style_message(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id) {
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int k = 0; k < modify->nfix; ++k) {
    const std::string m = fix_message(modify->fix[k], particles_id);
    if (!m.empty())
      return m;
  }
  for (int k = 0; k < modify->ncompute; ++k) {
    const std::string m = compute_message(modify->compute[k], particles_id);
    if (!m.empty())
      return m;
  }
  LAMMPS_NS::Output *output = lmp->output;
  for (int k = 0; k < output->ndump; ++k)
    if (const StyleRow *row = refused(StyleKind::dump, output->dump[k]->style))
      return message(std::string("dump ") + row->style + " (ID " + output->dump[k]->id + ")",
                     row->note, row->instead);
  LAMMPS_NS::Update *update = lmp->update;
  if (update->whichflag == 2) // init for a minimisation
    if (const StyleRow *row = refused(StyleKind::command, "minimize"))
      return message("minimize", row->note, row->instead);
  if (std::strncmp(update->integrate_style, "respa", 5) == 0)
    if (const StyleRow *row = refused(StyleKind::run_style, "respa"))
      return message("run_style respa", row->note, row->instead);
  return pair_message(lmp);
}

std::string gran_submodel_message(const std::string &style, const char *keyword,
                                  const char *value) {
  static const struct {
    const char *keyword;
    StyleKind kind;
  } kSubModels[] = {{"cohesion", StyleKind::gran_cohesion},
                    {"rolling_friction", StyleKind::gran_rolling},
                    {"surface", StyleKind::gran_surface}};
  for (const auto &sub : kSubModels) {
    if (std::strcmp(keyword, sub.keyword) != 0)
      continue;
    const StyleRow *row = value ? refused(sub.kind, value) : nullptr;
    const std::string what = style + ": pair gran's '" + keyword + " " + (value ? value : "") + "'";
    return what + " cannot work with triangulated particles: " +
           (row ? std::string(row->note) + "; instead use " + row->instead
                : std::string("pair gran's ") + keyword + " models are not available here");
  }
  return "";
}

void mend_output_frequencies(LAMMPS_NS::LAMMPS *lmp) {
  LAMMPS_NS::Modify *modify = lmp->modify;
  for (int k = 0; k < modify->nfix; ++k) {
    LAMMPS_NS::Fix *fix = modify->fix[k];
    if (fix->global_freq == 0 && (fix->scalar_flag || fix->vector_flag || fix->array_flag))
      fix->global_freq = 1;
  }
}

void refuse_incompatible_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &particles_id) {
  const std::string m = incompatible_style_message(lmp, particles_id);
  if (!m.empty())
    lmp->error->all(FLERR, m.c_str());
}

} // namespace tri_liggghts
