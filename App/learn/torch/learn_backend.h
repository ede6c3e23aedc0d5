// The learned-model backend of HoleFill: libtorch, linked into libholefill_learn.so
// and nowhere else (DESIGN.md); the core reaches the models through the C entry
// points of learn/learn_library.h. This header reports what backend the library
// has (holefill_learn_info, HoleFill.learnInfo(), the learn_backend ctest).
#pragma once

#include <string>

namespace holefill::learn {

// "libtorch <version> (<threads> threads)" after a real tensor round trip, or "unavailable: <why>".
std::string backendInfo();

// libtorch's intra-op threads; OpenBLAS, which libtorch calls for matrix products here, is held
// to one thread of its own: its pool and OpenMP's otherwise spin against each other on 2 cores
// (measured: a BIDGCN training step 1.6 times slower, a third of the time in sched_yield).
void setLearnThreads(int threads);

}  // namespace holefill::learn
