#include "contact_board.h"

#include <stdexcept>

namespace tri_liggghts {

int ContactBoard::join(const std::string &id, SourceKind kind) {
  for (std::size_t k = 0; k < sources_.size(); ++k)
    if (sources_[k].id == id) {
      sources_[k].kind = kind;
      return static_cast<int>(k);
    }
  sources_.push_back({id, kind, {}, {}, {}, false, {}, {}});
  return static_cast<int>(sources_.size()) - 1;
}

void ContactBoard::publish(int slot, const tri::InteractionTally &tally, IntersectingPair first) {
  if (slot < 0 || slot >= static_cast<int>(sources_.size()))
    throw std::out_of_range("ContactBoard::publish: no source in slot " + std::to_string(slot));
  sources_[slot].tally = tally;
  sources_[slot].first = first;
}

void ContactBoard::publish_deepest(int slot, const DeepestContact &deepest) {
  if (slot < 0 || slot >= static_cast<int>(sources_.size()))
    throw std::out_of_range("ContactBoard::publish_deepest: no source in slot " +
                            std::to_string(slot));
  sources_[slot].deepest = deepest;
}

DeepestContact ContactBoard::deepest() const {
  DeepestContact d;
  for (const Source &s : sources_)
    if (s.deepest.depth_of_limit > d.depth_of_limit)
      d = s.deepest;
  return d;
}

void DeepestContact::consider(const tri::PairForceResult &r, long a, long b,
                              const std::string &wall_id) {
  const double ratio = r.depth_of_limit();
  if (!(ratio > depth_of_limit))
    return;
  depth_of_limit = ratio;
  overlap = r.max_overlap;
  layer = r.layer;
  limit = r.depth_limit;
  tag_a = a;
  tag_b = b;
  wall = wall_id;
}

void ContactBoard::publish_material(int slot, const MaterialHint &hint) {
  if (slot < 0 || slot >= static_cast<int>(sources_.size()))
    throw std::out_of_range("ContactBoard::publish_material: no source in slot " +
                            std::to_string(slot));
  sources_[slot].has_material = true;
  sources_[slot].material = hint;
}

std::vector<ContactBoard::PublishedMaterial> ContactBoard::materials() const {
  std::vector<PublishedMaterial> out;
  for (const Source &s : sources_)
    if (s.has_material)
      out.push_back({s.kind, &s.id, &s.material});
  return out;
}

void ContactBoard::publish_contacts(int slot, std::vector<PublishedContact> &rows) {
  if (slot < 0 || slot >= static_cast<int>(sources_.size()))
    throw std::out_of_range("ContactBoard::publish_contacts: no source in slot " +
                            std::to_string(slot));
  sources_[slot].contacts.swap(rows);
}

static bool of_kind(SourceKind kind, TallySource which) {
  return which == TallySource::all ||
         (which == TallySource::pair && kind == SourceKind::particle_pairs) ||
         (which == TallySource::wall && kind == SourceKind::walls);
}

std::vector<const PublishedContact *> ContactBoard::contacts(TallySource which) const {
  std::vector<const PublishedContact *> out;
  for (const Source &s : sources_)
    if (of_kind(s.kind, which))
      for (const PublishedContact &c : s.contacts)
        out.push_back(&c);
  return out;
}

void ContactBoard::clear_tallies() {
  for (Source &s : sources_) {
    s.tally = tri::InteractionTally{};
    s.first = IntersectingPair{};
    s.deepest = DeepestContact{};
    s.contacts.clear();
  }
  fastest_pair_ = FastestPair{};
}

void ContactBoard::clear_sources() {
  sources_.clear();
  contacts_wanted_ = false;
  particle_pairs_ = nullptr;
  adaptive_dt_ = false;
}

void ContactBoard::end_run() {
  previous_ = {contacts_wanted_, sources_, particle_pairs_, adaptive_dt_, dtmin_, dtmax_};
  clear_sources();
}

void ContactBoard::restore_membership() {
  contacts_wanted_ = previous_.contacts_wanted;
  sources_ = previous_.sources;
  particle_pairs_ = previous_.particle_pairs;
  adaptive_dt_ = previous_.adaptive_dt;
  dtmin_ = previous_.dtmin;
  dtmax_ = previous_.dtmax;
}

int ContactBoard::sources(SourceKind kind) const {
  int n = 0;
  for (const Source &s : sources_)
    n += s.kind == kind;
  return n;
}

tri::InteractionTally ContactBoard::local(TallySource which) const {
  tri::InteractionTally t;
  for (const Source &s : sources_)
    if (of_kind(s.kind, which))
      t += s.tally;
  return t;
}

IntersectingPair ContactBoard::first_intersecting(SourceKind kind) const {
  for (const Source &s : sources_)
    if (s.kind == kind && s.first.found())
      return s.first;
  return {};
}

} // namespace tri_liggghts
