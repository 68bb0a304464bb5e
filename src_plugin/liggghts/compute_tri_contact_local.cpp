#include "compute_tri_contact_local.h"

#include "fix_tri_particles.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {
const char *kStyle = "Compute tri/contact/local";
// Keyword, columns; in the order of ComputeTriContactLocal::Value.
struct ValueName {
  const char *name;
  int columns;
};
const ValueName kValues[] = {{"pos", 6},          {"vel", 6},        {"id", 3},
                             {"force", 3},        {"force_normal", 3}, {"force_tangential", 3},
                             {"torque", 3},       {"contactArea", 1}, {"delta", 1},
                             {"contactPoint", 3}, {"normal", 3},      {"kind", 1}};
} // namespace

ComputeTriContactLocal::ComputeTriContactLocal(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg) {
  bool pair = false, wall = false, any_value = false;
  for (; iarg < narg; ++iarg) {
    const std::string key = arg[iarg];
    if (key == "pair") {
      pair = true;
      continue;
    }
    if (key == "wall") {
      wall = true;
      continue;
    }
    if (key == "history") // LIGGGHTS's per-pair history values: ours are per contact point
      error->all(FLERR, "Compute tri/contact/local: 'history' is not available (the shear "
                        "history is kept per contact point, not per pair)");
    int v = 0;
    while (v < num_values && key != kValues[v].name)
      ++v;
    if (v == num_values) {
      const std::string msg = std::string(kStyle) + ": unknown keyword '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
    value_[v] = any_value = true;
  }
  if (!any_value)
    for (bool &v : value_)
      v = true;
  source_ = pair == wall ? tri_liggghts::TallySource::all
            : pair       ? tri_liggghts::TallySource::pair
                         : tri_liggghts::TallySource::wall;
  for (int v = 0; v < num_values; ++v)
    columns_ += value_[v] ? kValues[v].columns : 0;
  local_flag = 1;
  size_local_rows = 0;
  vector_local = nullptr; // grown by compute_local (LIGGGHTS's Compute leaves them unset)
  array_local = nullptr;
  size_local_cols = columns_ == 1 ? 0 : columns_;
}

ComputeTriContactLocal::~ComputeTriContactLocal() {
  memory->destroy(vector_local);
  memory->destroy(array_local);
}

void ComputeTriContactLocal::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Compute tri/contact/local requires fix tri/particles");
  if (atom->map_style == 0)
    error->all(FLERR, "Compute tri/contact/local requires an atom map (atom_modify map array)");
  particles_->board().want_contacts();
}

bool ComputeTriContactLocal::wanted(const tri_liggghts::PublishedContact &c) const {
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  if (c.atom_a >= nlocal || !(mask[c.atom_a] & groupbit)) // a pair's row: where i is owned
    return false;
  return c.atom_b < 0 || (mask[c.atom_b] & groupbit);
}

void ComputeTriContactLocal::grow(int rows) {
  if (rows <= max_rows_)
    return;
  max_rows_ = rows;
  if (size_local_cols == 0) {
    memory->destroy(vector_local);
    memory->create(vector_local, max_rows_, "tri/contact/local:vector_local");
  } else {
    memory->destroy(array_local);
    memory->create(array_local, max_rows_, columns_, "tri/contact/local:array_local");
  }
}

void ComputeTriContactLocal::compute_local() {
  invoked_local = update->ntimestep;
  rows_.clear();
  for (const tri_liggghts::PublishedContact *c : particles_->published().contacts(source_))
    if (wanted(*c))
      rows_.push_back(c);
  const int n = static_cast<int>(rows_.size());
  grow(n > 0 ? n : 1);
  std::vector<double> row(columns_);
  for (int k = 0; k < n; ++k) {
    fill_row(*rows_[k], row.data());
    if (size_local_cols == 0)
      vector_local[k] = row[0];
    else
      std::memcpy(array_local[k], row.data(), sizeof(double) * columns_);
  }
  size_local_rows = n;
}

void ComputeTriContactLocal::fill_row(const tri_liggghts::PublishedContact &c, double *out) const {
  const tri::ContactRecord &r = c.contact;
  const bool wall = c.atom_b < 0;
  const int a = c.atom_a, b = c.atom_b;
  auto put3 = [&out](const double *v) {
    for (int d = 0; d < 3; ++d)
      *out++ = v[d];
  };
  const Eigen::Vector3d force_b = r.force_on_b(), normal_b = r.normal_force * r.normal;
  const Eigen::Vector3d on_a[3] = {-force_b, -normal_b, -r.tangential_force};
  if (value_[pos]) {
    put3(atom->x[a]);
    put3(wall ? r.point.data() : atom->x[b]);
  }
  if (value_[vel]) {
    put3(atom->v[a]);
    put3(wall ? r.velocity_b.data() : atom->v[b]);
  }
  if (value_[id]) {
    *out++ = static_cast<double>(atom->tag[a]);
    if (wall) {
      *out++ = -(c.wall_mesh + 1.0);
      *out++ = static_cast<double>(c.wall_triangle);
    } else {
      *out++ = static_cast<double>(atom->tag[b]);
      // A ghost across a periodic boundary is an image outside the box.
      bool periodic = false;
      for (int d = 0; d < 3; ++d)
        periodic = periodic || (domain->periodicity[d] &&
                                (atom->x[b][d] < domain->boxlo[d] || atom->x[b][d] >= domain->boxhi[d]));
      *out++ = periodic ? 1.0 : 0.0;
    }
  }
  for (int v = force; v <= force_tangential; ++v)
    if (value_[v])
      put3(on_a[v - force].data());
  if (value_[torque])
    put3(r.torque_a.data());
  if (value_[contact_area])
    *out++ = r.area;
  if (value_[delta])
    *out++ = r.overlap;
  if (value_[contact_point])
    put3(r.point.data());
  if (value_[normal])
    put3(r.normal.data());
  if (value_[kind])
    *out++ = static_cast<double>(static_cast<int>(r.kind));
}

double ComputeTriContactLocal::memory_usage() {
  return static_cast<double>(max_rows_) * columns_ * sizeof(double) +
         static_cast<double>(rows_.capacity() * sizeof(void *));
}
