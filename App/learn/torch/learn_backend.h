// The learned-model backend of HoleFill: libtorch, linked into libholefill_learn.so
// and nowhere else (DESIGN.md); the core reaches the models through the C entry
// points of learn/learn_library.h. This header reports what backend the library
// has (holefill_learn_info, HoleFill.learnInfo(), the learn_backend ctest).
#pragma once

#include <string>

namespace holefill::learn {

// "libtorch <version> (<threads> threads)" after a real tensor round trip, or "unavailable: <why>".
std::string backendInfo();

}  // namespace holefill::learn
