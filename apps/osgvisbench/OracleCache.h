// SPDX-License-Identifier: MIT
#pragma once
// The oracle's exact sets kept on disk between runs (--oracle-cache DIR): rendering the oracle is the
// slowest part of a short bench run, and a loop over real models reruns the same models, walks and
// sizes many times while only the modes change. A file is named by a key over everything the exact
// sets depend on; a file that does not match its key, or is damaged, is ignored and rendered again.
#include "BenchView.h"
#include "OracleReference.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace osgVis::bench
{
// FNV-1a 64 over the model's geometry (core::sceneGeometryFingerprint of an extraction with
// triangles, so an edited wall or a changed loader gives a new key even where bounds stay), the
// object count, every view's matrices, the size and the supersampling factor.
std::uint64_t oracleCacheKey(const ExtractedScene& withTriangles, const std::vector<BenchView>& views,
                             unsigned width, unsigned height, unsigned supersample);

// DIR/oracle-<key as 16 hex digits>.bin
std::string oracleCacheFile(const std::string& dir, std::uint64_t key);

// The reference stored under `key` for a scene of `objectCount` objects, with inFrustum left empty
// (it is cheap: the caller recomputes it); nothing when the file is missing, of another key or
// malformed (said on stderr, except for a missing file).
std::optional<OracleReference> loadOracleReference(const std::string& file, std::uint64_t key,
                                                   std::size_t objectCount);

// Writes through a temporary file renamed into place, so a run killed halfway leaves no file that
// looks whole. Throws std::runtime_error when the directory cannot be written.
void saveOracleReference(const std::string& file, std::uint64_t key, const OracleReference& reference);

// computeOracleReference, or what an earlier run stored under DIR for the same key (then no GL is
// touched); a computed reference is stored for the next run.
OracleReference cachedOracleReference(const std::string& dir, osg::Node& root, const ExtractedScene& scene,
                                      const std::vector<BenchView>& views, unsigned width, unsigned height,
                                      unsigned supersample);
} // namespace osgVis::bench
