#pragma once
// Tolerances a drawing writes (issue 28, item 2): ISO 286 tolerance classes
// ("h7", "H7", "g6", "js6", "K7") computed from the standard's tables of
// standard tolerance grades (IT1-IT18) and fundamental deviations for basic
// sizes up to 500 mm, and ISO 2768-1 general tolerances (f, m, c, v) for the
// dimensions that have none of their own.
//
//   isoFit("h7", 25.0)   // {upper 0, lower -0.021, "h7"}
//   isoFit("H7", 40.0)   // {+0.025, 0, "H7"}
#include <optional>
#include <string>

#include "klueng/core/cut/inspection.h"

namespace klueng::core::design {

// The limit deviations of an ISO 286 class at a basic size (0 < size <= 500
// mm), or nullopt when the class is not one Klueng's tables hold: shafts c, d,
// e, f, g, h, js, k, m, n, p, r, s and holes C, D, E, F, G, H, JS, K, M, N, P,
// R, S, grades 1-18 (K, M, N up to grade 8 as the standard gives them, P-S up
// to 7 with the Δ rule, above it without).
std::optional<cut::Tolerance> isoFit(const std::string& toleranceClass, double size);
// The letters and grades isoFit knows, for messages.
inline constexpr const char* kIsoFitsKnown =
    "c d e f g h js k m n p r s (shafts), C D E F G H JS K M N P R S (holes), grades 1-18, Ø up to 500 mm";

// ISO 2768-1 general tolerance (class "f", "m", "c" or "v") of a linear size
// (0.5 < size <= 4000 mm), or nullopt (a class v size up to 3 mm has none).
std::optional<cut::Tolerance> generalTolerance(const std::string& toleranceClass, double size);

}  // namespace klueng::core::design
