// SPDX-License-Identifier: MIT
#pragma once
// osgvisrawgl's OpenGL 3.3 core renderer: a GLFW window (hidden unless shown) whose context draws
// into an off-screen framebuffer of the walk's size, so frames can be read back pixel for pixel.
// The GL entry points come from glfwGetProcAddress (no loader library). Objects are lit by their
// normal in their material's base colour; depth test on; back faces culled for one-sided materials
// (OSGVIS_OBJECT_CULL_BACK), as OSG draws the glTF plugin's graph.
#include "RawScene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace osgVis::rawgl
{
struct GlError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

class RawRenderer
{
public:
    // The background's RGBA bytes in a frame read back.
    static constexpr std::uint8_t ClearColor[4] = {51, 51, 102, 255};

    // Opens the window and its GL 3.3 core context and uploads `scene`. Throws GlError.
    RawRenderer(const RawScene& scene, unsigned width, unsigned height, bool show);
    ~RawRenderer();
    RawRenderer(const RawRenderer&) = delete;
    RawRenderer& operator=(const RawRenderer&) = delete;

    // Draws the objects whose `drawn` entry is true (every object when `drawn` is empty) with the
    // given world → eye and eye → clip matrices, into the off-screen frame (and the window when shown).
    void render(const glm::dmat4& view, const glm::dmat4& projection, const std::vector<bool>& drawn);
    // The last frame's RGBA pixels, bottom row first.
    void readPixels(std::vector<std::uint8_t>& rgba);
    // False once the user closed a shown window.
    bool open() const;

private:
    struct Impl;
    std::unique_ptr<Impl> _impl;
};
} // namespace osgVis::rawgl
