#pragma once
// Update-cost sampling shared by bench/wellspaced and the audit: inserts and then erases each extra
// point (the input is unchanged afterwards) and returns the mean time and operations per update.
#include <cstdint>
#include <vector>

#include "wellspaced/well_spaced_set.hpp"

namespace kmr::wellspaced {

struct UpdateSample {
  double mean_seconds = 0;   // per insertion or deletion
  double mean_touched = 0;   // obsolete + fresh + inconsistent operations per update
  std::uint64_t updates = 0;
};

template <std::size_t D>
UpdateSample sample_updates(WellSpacedSet<D>& ws, const std::vector<Point<D>>& extra) {
  UpdateSample s;
  double seconds = 0;
  std::uint64_t touched = 0;
  for (const auto& p : extra) {
    for (const UpdateStats& u : {ws.insert(p), ws.erase(p)}) {
      seconds += u.seconds;
      touched += u.touched();
      ++s.updates;
    }
  }
  if (s.updates) {
    s.mean_seconds = seconds / double(s.updates);
    s.mean_touched = double(touched) / double(s.updates);
  }
  return s;
}

}  // namespace kmr::wellspaced
