// fix tri/kept_contacts: the kept contact points of pair tri/gran's particle pairs
// (kept_contact_store.h), created by the pair style itself (as LIGGGHTS's pair gran creates fix
// contacthistory) when `keep_contacts` is on. Not for input decks.
//
// It moves the records with the atoms: before LIGGGHTS exchanges atoms between ranks, each
// record is parcelled with the local atoms that may evaluate it next; after the exchange, the
// parcels go back into the store. Restart files get the same parcels (per-atom restart data),
// so a run read from a restart carries the same contacts as the run that wrote it.
#pragma once

#include "fix.h"

#include "kept_contact_store.h"

#include <vector>

namespace LAMMPS_NS {

class FixTriKeptContacts : public Fix {
public:
  FixTriKeptContacts(class LAMMPS *, int, char **);
  ~FixTriKeptContacts() override;
  int setmask() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void setup_pre_neighbor() override { pre_neighbor(); }
  void pre_neighbor() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  tri_liggghts::KeptContactStore &store() { return store_; }

private:
  tri_liggghts::KeptContactStore store_;
  std::vector<std::vector<double>> parcels_; // per local atom, between exchange and rebuild
  // A restart file's copy of the store, by local atom (the store stays as it is).
  std::vector<std::vector<double>> restart_parcels_;
  bigint restart_parcels_step_ = -1;
  bool other_layout_read_ = false; // a restart file's parcels of another layout were dropped
  void parcel(std::vector<std::vector<double>> &out, bool drain);
  const std::vector<double> &restart_parcel(int i);
  int largest_exchange() const; // doubles, over the local atoms
};

} // namespace LAMMPS_NS
