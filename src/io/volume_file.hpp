// The raw field as a volume file: FIELD.r32 holds the (2^R+1)^3 lattice as float32
// little-endian, x fastest, then y, then z, with the sidecar FIELD.r32.json beside it (size,
// order, value range, the field's parameters, provenance; keys as in docs/formats.md). Written
// plane by plane, so Types III and IV write a lattice that never sits in memory whole; written atomically (no partial file is left).
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "solid/evaluator.hpp"

namespace sansui::io {

/// Writes every lattice point of `field`. `provenance` is stored under "provenance" in the
/// sidecar. Uses clones of `field` on all threads (Type II: the field itself, one thread, so
/// its one map serves every query). Throws InputError if the file cannot be written.
void write_volume_r32(const std::filesystem::path& path, solid::FieldEvaluator& field, const nlohmann::json& provenance,
                      const Context& context = quiet_context());

/// One z-plane of the lattice, (2^R+1)^2 values, x fastest; rows in parallel as above.
void evaluate_plane(solid::FieldEvaluator& field, int z, float* out);

}  // namespace sansui::io
