#include "contact_board.h"

#include <stdexcept>

namespace tri_liggghts {

int ContactBoard::join(const std::string &id, SourceKind kind) {
  for (std::size_t k = 0; k < sources_.size(); ++k)
    if (sources_[k].id == id) {
      sources_[k].kind = kind;
      return static_cast<int>(k);
    }
  sources_.push_back({id, kind, {}, {}, false, {}});
  return static_cast<int>(sources_.size()) - 1;
}

void ContactBoard::publish(int slot, const tri::InteractionTally &tally, IntersectingPair first) {
  if (slot < 0 || slot >= static_cast<int>(sources_.size()))
    throw std::out_of_range("ContactBoard::publish: no source in slot " + std::to_string(slot));
  sources_[slot].tally = tally;
  sources_[slot].first = first;
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

void ContactBoard::clear_tallies() {
  for (Source &s : sources_) {
    s.tally = tri::InteractionTally{};
    s.first = IntersectingPair{};
  }
}

void ContactBoard::clear_sources() {
  sources_.clear();
  particle_pairs_ = nullptr;
  adaptive_dt_ = false;
}

int ContactBoard::sources(SourceKind kind) const {
  int n = 0;
  for (const Source &s : sources_)
    n += s.kind == kind;
  return n;
}

tri::InteractionTally ContactBoard::local(TallySource which) const {
  tri::InteractionTally t;
  for (const Source &s : sources_) {
    const bool wanted = which == TallySource::all ||
                        (which == TallySource::pair && s.kind == SourceKind::particle_pairs) ||
                        (which == TallySource::wall && s.kind == SourceKind::walls);
    if (wanted)
      t += s.tally;
  }
  return t;
}

IntersectingPair ContactBoard::first_intersecting(SourceKind kind) const {
  for (const Source &s : sources_)
    if (s.kind == kind && s.first.found())
      return s.first;
  return {};
}

} // namespace tri_liggghts
