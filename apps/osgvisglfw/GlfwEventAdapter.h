// SPDX-License-Identifier: MIT
#pragma once
// Forwards a GLFW window's input (keys, mouse buttons, cursor, scroll, framebuffer size) to the
// event queue of an osgViewer::GraphicsWindowEmbedded, so OSG's manipulators and event handlers
// work in a window the application owns. Positions are in framebuffer pixels, y down (OSG's default
// for window events), so they match the viewport on high-DPI screens too.
#include <osgViewer/GraphicsWindow>

struct GLFWwindow;

namespace osgVis::glfwapp
{
class GlfwEventAdapter
{
public:
    // Installs the callbacks on `window` and takes its user pointer until destroyed.
    GlfwEventAdapter(GLFWwindow* window, osgViewer::GraphicsWindowEmbedded* embedded);
    ~GlfwEventAdapter();
    GlfwEventAdapter(const GlfwEventAdapter&) = delete;
    GlfwEventAdapter& operator=(const GlfwEventAdapter&) = delete;

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onCursor(GLFWwindow* window, double x, double y);
    static void onScroll(GLFWwindow* window, double dx, double dy);
    static void onFramebufferSize(GLFWwindow* window, int width, int height);

    osgGA::EventQueue& queue() const { return *_embedded->getEventQueue(); }
    // Window (screen) coordinates → framebuffer pixels.
    void toPixels(double& x, double& y) const;

    GLFWwindow* _window;
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> _embedded;
};

// The OSG key symbol of a GLFW key (letters lower case unless shift is held), or 0 for keys OSG
// has no symbol for.
int osgKeySymbol(int glfwKey, int glfwMods);
// GLFW_MOD_* bits as osgGA::GUIEventAdapter::MODKEY_* bits.
int osgModKeyMask(int glfwMods);
} // namespace osgVis::glfwapp
