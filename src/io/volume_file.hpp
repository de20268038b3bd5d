// Volumes as r32 files: VOLUME.r32 holds a cube of side^3 float32 samples, little-endian, x
// fastest, then y, then z, with the sidecar VOLUME.r32.json beside it (size, order, value range,
// what the caller says of the volume, provenance; keys as in docs/formats.md). Written plane by
// plane from a callback, so a volume never has to sit in memory whole; written atomically (no
// partial file is left). Plain data: the solid texture's field is turned into planes by its
// caller (solid::evaluate_plane).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/context.hpp"

namespace sansui::io {

struct Volume {
  int side = 0;
  /// Fills plane z (side^2 values, x fastest) of the cube.
  std::function<void(int z, float* plane)> plane;
  std::string description;                          ///< what a sample is, for the sidecar's "format"
  nlohmann::json about = nlohmann::json::object();  ///< more sidecar keys (the field's parameters)
};

/// Writes every sample of `volume`. `provenance` is stored under "provenance" in the sidecar.
/// Throws InputError if the file cannot be written.
void write_volume_r32(const std::filesystem::path& path, const Volume& volume, const nlohmann::json& provenance,
                      const Context& context = quiet_context());

}  // namespace sansui::io
