#include "fix_tri_kept_contacts.h"

#include "peratom_restart.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "update.h"

#include <algorithm>
#include <unordered_map>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriKeptContacts::FixTriKeptContacts(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  if (narg != 3)
    error->all(FLERR, "Fix tri/kept_contacts takes no arguments (pair tri/gran creates it)");
  restart_peratom = 1;
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
}

FixTriKeptContacts::~FixTriKeptContacts() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
}

int FixTriKeptContacts::setmask() { return PRE_EXCHANGE | PRE_NEIGHBOR; }

void FixTriKeptContacts::parcel(std::vector<std::vector<double>> &out, bool drain) {
  // By tag, not through LIGGGHTS's atom map, which a deck need not have.
  const int nlocal = atom->nlocal;
  std::unordered_map<long long, int> local;
  local.reserve(static_cast<std::size_t>(nlocal));
  for (int i = 0; i < nlocal; ++i)
    local.emplace(atom->tag[i], i);
  auto local_of = [&local](long long tag) {
    const auto it = local.find(tag);
    return it == local.end() ? -1 : it->second;
  };
  store_.to_parcels(local_of, out, drain);
}

void FixTriKeptContacts::pre_exchange() {
  // Parcels already held (read from a restart file) are kept beside the store's.
  parcel(parcels_, true);
  comm->maxexchange_fix = std::max(comm->maxexchange_fix, largest_exchange() + 1);
}

void FixTriKeptContacts::pre_neighbor() { store_.from_parcels(parcels_, atom->nlocal); }

int FixTriKeptContacts::largest_exchange() const {
  std::size_t most = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    most = std::max(most, parcels_[i].size());
  int local = static_cast<int>(most) + 1, all = 0;
  MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MAX, world);
  return all;
}

void FixTriKeptContacts::grow_arrays(int nmax) {
  parcels_.resize(static_cast<std::size_t>(nmax));
}

void FixTriKeptContacts::copy_arrays(int i, int j, int) { parcels_[j] = parcels_[i]; }

void FixTriKeptContacts::set_arrays(int i) { parcels_[i].clear(); }

int FixTriKeptContacts::pack_exchange(int i, double *buf) {
  const std::vector<double> &p = parcels_[i];
  buf[0] = static_cast<double>(p.size());
  std::copy(p.begin(), p.end(), buf + 1);
  return static_cast<int>(p.size()) + 1;
}

int FixTriKeptContacts::unpack_exchange(int nlocal, double *buf) {
  const auto n = static_cast<std::size_t>(buf[0]);
  parcels_[nlocal].assign(buf + 1, buf + 1 + n);
  return static_cast<int>(n) + 1;
}

// A restart is written from the store as it is (between rebuilds the parcels are empty): one
// copy per write, made at its first request.
const std::vector<double> &FixTriKeptContacts::restart_parcel(int i) {
  if (restart_parcels_step_ != update->ntimestep || restart_parcels_.size() < parcels_.size()) {
    restart_parcels_.assign(parcels_.size(), {});
    for (int k = 0; k < atom->nlocal; ++k)
      restart_parcels_[k] = parcels_[k];
    parcel(restart_parcels_, false);
    restart_parcels_step_ = update->ntimestep;
  }
  return restart_parcels_[i];
}

// An atom's restart record: its length, then (where it has parcels) the record layout,
// tri::kKeptContactDoubles, and the parcels. Parcels of another layout are not read.
namespace {
int restart_size(const std::vector<double> &parcels) {
  return parcels.empty() ? 1 : static_cast<int>(parcels.size()) + 2;
}
} // namespace

int FixTriKeptContacts::pack_restart(int i, double *buf) {
  const std::vector<double> &p = restart_parcel(i);
  buf[0] = restart_size(p);
  if (!p.empty()) {
    buf[1] = tri::kKeptContactDoubles;
    std::copy(p.begin(), p.end(), buf + 2);
  }
  return restart_size(p);
}

void FixTriKeptContacts::unpack_restart(int nlocal, int nth) {
  const double *record = tri_liggghts::restart_record(atom->extra, nlocal, nth);
  const int n = static_cast<int>(record[-1]) - 1;
  parcels_[nlocal].clear();
  if (n <= 0)
    return;
  if (record[0] != tri::kKeptContactDoubles) { // another layout: the pair is measured afresh
    other_layout_read_ = true;
    return;
  }
  if ((n - 1) % tri_liggghts::KeptContactStore::kParcelDoubles != 0)
    error->one(FLERR, "Fix tri/kept_contacts: the restart file's kept contacts are damaged "
                      "(their length does not match their layout)");
  parcels_[nlocal].assign(record + 1, record + n);
}

void FixTriKeptContacts::setup_pre_exchange() {
  int mine = other_layout_read_ ? 1 : 0, any = 0;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  if (any && comm->me == 0)
    error->warning(FLERR, "Fix tri/kept_contacts: the restart file keeps contact points in "
                          "another layout (another version): they are measured afresh");
  other_layout_read_ = false;
  pre_exchange();
}

int FixTriKeptContacts::size_restart(int i) { return restart_size(restart_parcel(i)); }

int FixTriKeptContacts::maxsize_restart() {
  std::size_t most = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    most = std::max(most, restart_parcel(i).size());
  int local = static_cast<int>(most) + 2, all = 0;
  MPI_Allreduce(&local, &all, 1, MPI_INT, MPI_MAX, world);
  return all;
}

double FixTriKeptContacts::memory_usage() {
  double bytes = static_cast<double>(store_.bytes());
  for (const auto &p : parcels_)
    bytes += static_cast<double>(p.capacity() * sizeof(double) + sizeof(p));
  return bytes;
}
