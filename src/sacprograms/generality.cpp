// Appendix A.2 shapes over kmr::sac (issue 8 §1): certificates created in the run, destination
// memo with reads, a write that moves earlier. See generality.hpp.
#include "sacprograms/generality.hpp"

namespace kmr::sacprograms {

std::uint64_t input_cell_name(std::uint64_t id) { return sac::mix(sac::fnv("in.cell"), id); }

// ---- certified filter ---------------------------------------------------------------------------
bool certificate_truth(const std::map<std::uint64_t, bool>& flips, std::uint64_t name) {
  auto f = flips.find(name);
  return f != flips.end() ? f->second : (sac::mix(name, 0xce27) & 1) != 0;
}

void CertificateOwner::flip(std::uint64_t name) {
  bool v = !truth(name);
  flips_[name] = v;
  auto l = live_.find(name);
  if (l != live_.end()) rt_->change(l->second.cert, v);
}

void CertificateOwner::created(std::uint64_t name, Mod<bool>* cert, sac::HookId hook) {
  live_[name] = Registration{cert, hook};  // replaces a predecessor whose hook has not run yet
}

void CertificateOwner::discarded(std::uint64_t name, sac::HookId self) {
  discards_.push_back(self);
  auto l = live_.find(name);
  if (l != live_.end() && l->second.hook == self) live_.erase(l);  // not a successor's registration
}

std::vector<sac::HookId> CertificateOwner::take_discards() {
  std::vector<sac::HookId> d;
  d.swap(discards_);
  return d;
}

namespace {
constexpr Label kCfStep{"cf.step"}, kCfCert{"cf.cert"}, kCfHook{"cf.hook"}, kCfCell{"cf.cell"}, kCfOut{"cf.out"};

Unit cf_step(Runtime* rt, CertificateOwner* o, List* l, List* dest) {
  return rt->memo<Unit>(kCfStep, std::make_tuple(l, dest), [rt, o, l, dest] {
    rt->read(l, [rt, o, l, dest](const Cell& c) {
      if (c.nil) {
        rt->write(dest, Cell{});
        return;
      }
      std::uint64_t name = l->name;
      Mod<bool>* cert = rt->traceable<bool>(kCfCert, o->truth(name), l);
      sac::HookId id = rt->on_discard(kCfHook, [o, name](sac::HookId self) { o->discarded(name, self); });
      o->created(name, cert, id);
      long long h = c.head;
      List* tail = c.tail;
      rt->read(cert, [rt, o, l, dest, h, tail](bool holds) {
        if (holds) {
          List* cell = rt->alloc<Cell>(kCfCell, l);
          rt->write(dest, Cell{false, h, cell});
          cf_step(rt, o, tail, cell);
        } else {
          cf_step(rt, o, tail, dest);
        }
      });
    });
    return Unit{};
  });
}
}  // namespace

Root* sa_certified_filter(Runtime& rt, Root* in, CertificateOwner* owner) {
  return rt.run([r = &rt, in, owner] {
    Root* out = r->alloc<List*>(kCfOut);
    r->read(in, [r, out, owner](List* l) {
      List* head = r->alloc<Cell>(kCfCell, 0);
      r->write(out, head);
      cf_step(r, owner, l, head);
    });
    return out;
  });
}

std::vector<long long> static_certified_filter(const std::vector<long long>& values,
                                               const std::vector<std::uint64_t>& ids,
                                               const std::map<std::uint64_t, bool>& flips) {
  std::vector<long long> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (certificate_truth(flips, input_cell_name(ids[i]))) out.push_back(values[i]);
  return out;
}

// ---- next greater: destination-passing memo ----------------------------------------------------
namespace {
constexpr Label kNgSearch{"ng.search"}, kNg{"ng"}, kNgCell{"ng.cell"}, kNgOut{"ng.out"}, kNgBox{"ng.box"};

// ΔML `mfun search`: the first element of l greater than t; the result depends on the reads.
Mod<long long>* ng_search(Runtime* rt, List* l, long long t) {
  return rt->memo_box<long long>(kNgSearch, std::make_tuple(l, t), [rt, l, t](Mod<long long>* dest) {
    rt->read(l, [rt, t, dest](const Cell& c) {
      if (c.nil) rt->write(dest, kNoGreater);
      else if (c.head > t) {
        // ΔML `Box.put` then `Box.get`: a fresh box read right after its write (§1 item 5).
        Mod<long long>* box = rt->put<long long>(kNgBox, c.head);
        rt->read(box, [rt, dest](long long v) { rt->write(dest, v); });
      } else rt->read(ng_search(rt, c.tail, t), [rt, dest](long long v) { rt->write(dest, v); });
    });
  });
}

Unit ng_step(Runtime* rt, List* l, List* dest) {
  return rt->memo<Unit>(kNg, std::make_tuple(l, dest), [rt, l, dest] {
    rt->read(l, [rt, l, dest](const Cell& c) {
      if (c.nil) {
        rt->write(dest, Cell{});
        return;
      }
      List* cell = rt->alloc<Cell>(kNgCell, l);
      rt->read(ng_search(rt, c.tail, c.head), [rt, dest, cell](long long v) { rt->write(dest, Cell{false, v, cell}); });
      ng_step(rt, c.tail, cell);
    });
    return Unit{};
  });
}
}  // namespace

Root* sa_next_greater(Runtime& rt, Root* in) {
  return rt.run([r = &rt, in] {
    Root* out = r->alloc<List*>(kNgOut);
    r->read(in, [r, out](List* l) {
      List* head = r->alloc<Cell>(kNgCell, 0);
      r->write(out, head);
      ng_step(r, l, head);
    });
    return out;
  });
}

std::vector<long long> static_next_greater(const std::vector<long long>& values) {
  std::vector<long long> out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    long long g = kNoGreater;
    for (std::size_t j = i + 1; j < values.size(); ++j)
      if (values[j] > values[i]) {
        g = values[j];
        break;
      }
    out.push_back(g);
  }
  return out;
}

// ---- first positive: a write that moves earlier ------------------------------------------------
namespace {
constexpr Label kFpA{"fp.scan"}, kFpCount{"fp.count"}, kFpOut{"fp.out"}, kFpFound{"fp.found"};

// First pass: writes out := the first positive element (and found := true), or found := false.
Unit fp_scan(Runtime* rt, List* l, Mod<long long>* out, Mod<bool>* found) {
  return rt->memo<Unit>(kFpA, l, [rt, l, out, found] {
    rt->read(l, [rt, out, found](const Cell& c) {
      if (c.nil) {
        rt->write(found, false);
      } else if (c.head > 0) {
        rt->write(out, c.head);
        rt->write(found, true);
      } else {
        fp_scan(rt, c.tail, out, found);
      }
    });
    return Unit{};
  });
}
// Second pass (only if nothing was found): out := the number of elements.
Unit fp_count(Runtime* rt, List* l, long long k, Mod<long long>* out) {
  return rt->memo<Unit>(kFpCount, std::make_tuple(l, k), [rt, l, k, out] {
    rt->read(l, [rt, k, out](const Cell& c) {
      if (c.nil) rt->write(out, k);
      else fp_count(rt, c.tail, k + 1, out);
    });
    return Unit{};
  });
}
}  // namespace

Mod<long long>* sa_first_positive(Runtime& rt, Root* in) {
  return rt.run([r = &rt, in] {
    Mod<long long>* out = r->alloc<long long>(kFpOut);
    Mod<bool>* found = r->alloc<bool>(kFpFound);
    r->read(in, [r, out, found](List* l) {
      fp_scan(r, l, out, found);
      r->read(found, [r, l, out](bool f) {
        if (!f) fp_count(r, l, 0, out);
      });
    });
    return out;
  });
}

long long static_first_positive(const std::vector<long long>& values) {
  for (long long v : values)
    if (v > 0) return v;
  return static_cast<long long>(values.size());
}

}  // namespace kmr::sacprograms
