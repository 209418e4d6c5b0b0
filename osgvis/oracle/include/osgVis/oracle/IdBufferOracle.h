// SPDX-License-Identifier: MIT
#pragma once

#include <osgVis/oracle/OracleObject.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace osgVis::oracle
{
struct OracleSettings
{
    unsigned width = 1280, height = 1024; // pixels of the display resolution being judged
    unsigned supersample = 2;             // a second render at supersample× width and height; <= 1: none
};

class IdRenderer;

// Exact visibility by an item-buffer render of the real OSG graph: every object draws its own
// drawable with its own state (cull face, polygon mode, ...) and its own ID colour, depth-tested
// against all opaque geometry, at the display resolution and at supersample× it. The union is the
// visible set. Transparent objects (see OracleObject::transparent) hide nothing; one counts as
// visible when it has a pixel in front of the opaque depth.
//
// Owns one offscreen (pbuffer + FBO) viewer per resolution, made current only inside visible(), so
// another viewer in the same process is not disturbed. Needs a display (Xvfb). Not thread-safe.
// note: while it lives, its transforms are extra parents of the application's drawables
// (Drawable::getParentalNodePaths() sees them); they go with it.
class IdBufferOracle
{
public:
    IdBufferOracle(osg::Node* root, const OracleSettings& settings); // throws std::runtime_error
    ~IdBufferOracle();
    IdBufferOracle(const IdBufferOracle&) = delete;
    IdBufferOracle& operator=(const IdBufferOracle&) = delete;

    const std::vector<OracleObject>& objects() const { return _objects; }
    const OracleSettings& settings() const { return _settings; }

    struct Result
    {
        std::vector<std::uint32_t> visible;  // indices into objects(), ascending
        std::size_t onlyInSupersampled = 0;  // of those, found only by the supersampled render
        // Parallel to visible: the object's pixels in the display-resolution image (0 for those found
        // only by the supersampled render).
        std::vector<std::uint32_t> pixels;
    };
    // view and projection are used as given (no near/far recomputation, no small-feature culling).
    Result visible(const osg::Matrixd& view, const osg::Matrixd& projection);

private:
    OracleSettings _settings;
    std::vector<OracleObject> _objects;
    std::unique_ptr<IdRenderer> _display;      // width × height
    std::unique_ptr<IdRenderer> _supersampled; // supersample× width × height, or null
    std::vector<std::uint8_t> _seenDisplay;    // per object, reused between calls
    std::vector<std::uint8_t> _seenSupersampled;
    std::vector<std::uint32_t> _pixelsDisplay;
};
} // namespace osgVis::oracle
