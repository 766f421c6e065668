#pragma once
// The programs' entry points, shared by registry.cpp (not part of the public interface).
#include "sacprograms/programs.hpp"

namespace kmr::sacprograms {

Root* sa_map(Runtime& rt, Root* in);
Root* sa_filter(Runtime& rt, Root* in);
Mod<long long>* sa_sum(Runtime& rt, Root* in);
Root* sa_quicksort(Runtime& rt, Root* in);
Root* sa_mergesort(Runtime& rt, Root* in);
Root* sa_quickhull(Runtime& rt, Root* in);

SCell* static_map(const SCell* l, SArena& a);
SCell* static_filter(const SCell* l, SArena& a);
long long static_sum(const SCell* l);
SCell* static_quicksort(const SCell* l, SArena& a);
SCell* static_mergesort(const SCell* l, SArena& a);
std::vector<long long> static_quickhull(const SCell* l);

}  // namespace kmr::sacprograms
