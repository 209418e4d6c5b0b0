// SPDX-License-Identifier: MIT
#include "GlfwEventAdapter.h"

#define GLFW_INCLUDE_NONE // OSG brings the GL headers
#include <GLFW/glfw3.h>

namespace osgVis::glfwapp
{
namespace
{
using Key = osgGA::GUIEventAdapter::KeySymbol;

GlfwEventAdapter& adapterOf(GLFWwindow* window)
{
    return *static_cast<GlfwEventAdapter*>(glfwGetWindowUserPointer(window));
}
} // namespace

int osgKeySymbol(int glfwKey, int glfwMods)
{
    // GLFW names printable keys by their US-layout ASCII code, upper case for letters.
    if (glfwKey >= GLFW_KEY_A && glfwKey <= GLFW_KEY_Z)
        return (glfwMods & GLFW_MOD_SHIFT) ? glfwKey : glfwKey - GLFW_KEY_A + 'a';
    if (glfwKey >= GLFW_KEY_SPACE && glfwKey <= GLFW_KEY_GRAVE_ACCENT)
        return glfwKey;
    if (glfwKey >= GLFW_KEY_F1 && glfwKey <= GLFW_KEY_F12)
        return Key::KEY_F1 + (glfwKey - GLFW_KEY_F1);
    if (glfwKey >= GLFW_KEY_KP_0 && glfwKey <= GLFW_KEY_KP_9)
        return Key::KEY_KP_0 + (glfwKey - GLFW_KEY_KP_0);
    switch (glfwKey)
    {
    case GLFW_KEY_ESCAPE:
        return Key::KEY_Escape;
    case GLFW_KEY_ENTER:
        return Key::KEY_Return;
    case GLFW_KEY_KP_ENTER:
        return Key::KEY_KP_Enter;
    case GLFW_KEY_TAB:
        return Key::KEY_Tab;
    case GLFW_KEY_BACKSPACE:
        return Key::KEY_BackSpace;
    case GLFW_KEY_INSERT:
        return Key::KEY_Insert;
    case GLFW_KEY_DELETE:
        return Key::KEY_Delete;
    case GLFW_KEY_RIGHT:
        return Key::KEY_Right;
    case GLFW_KEY_LEFT:
        return Key::KEY_Left;
    case GLFW_KEY_DOWN:
        return Key::KEY_Down;
    case GLFW_KEY_UP:
        return Key::KEY_Up;
    case GLFW_KEY_PAGE_UP:
        return Key::KEY_Page_Up;
    case GLFW_KEY_PAGE_DOWN:
        return Key::KEY_Page_Down;
    case GLFW_KEY_HOME:
        return Key::KEY_Home;
    case GLFW_KEY_END:
        return Key::KEY_End;
    case GLFW_KEY_LEFT_SHIFT:
        return Key::KEY_Shift_L;
    case GLFW_KEY_RIGHT_SHIFT:
        return Key::KEY_Shift_R;
    case GLFW_KEY_LEFT_CONTROL:
        return Key::KEY_Control_L;
    case GLFW_KEY_RIGHT_CONTROL:
        return Key::KEY_Control_R;
    case GLFW_KEY_LEFT_ALT:
        return Key::KEY_Alt_L;
    case GLFW_KEY_RIGHT_ALT:
        return Key::KEY_Alt_R;
    case GLFW_KEY_LEFT_SUPER:
        return Key::KEY_Super_L;
    case GLFW_KEY_RIGHT_SUPER:
        return Key::KEY_Super_R;
    default:
        return 0;
    }
}

int osgModKeyMask(int glfwMods)
{
    using Mod = osgGA::GUIEventAdapter::ModKeyMask;
    int mask = 0;
    if (glfwMods & GLFW_MOD_SHIFT)
        mask |= Mod::MODKEY_SHIFT;
    if (glfwMods & GLFW_MOD_CONTROL)
        mask |= Mod::MODKEY_CTRL;
    if (glfwMods & GLFW_MOD_ALT)
        mask |= Mod::MODKEY_ALT;
    if (glfwMods & GLFW_MOD_SUPER)
        mask |= Mod::MODKEY_SUPER;
    return mask;
}

GlfwEventAdapter::GlfwEventAdapter(GLFWwindow* window, osgViewer::GraphicsWindowEmbedded* embedded)
    : _window(window), _embedded(embedded)
{
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, onKey);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetScrollCallback(window, onScroll);
    glfwSetFramebufferSizeCallback(window, onFramebufferSize);
}

GlfwEventAdapter::~GlfwEventAdapter()
{
    glfwSetKeyCallback(_window, nullptr);
    glfwSetMouseButtonCallback(_window, nullptr);
    glfwSetCursorPosCallback(_window, nullptr);
    glfwSetScrollCallback(_window, nullptr);
    glfwSetFramebufferSizeCallback(_window, nullptr);
    glfwSetWindowUserPointer(_window, nullptr);
}

void GlfwEventAdapter::toPixels(double& x, double& y) const
{
    int windowWidth = 0, windowHeight = 0, pixelWidth = 0, pixelHeight = 0;
    glfwGetWindowSize(_window, &windowWidth, &windowHeight);
    glfwGetFramebufferSize(_window, &pixelWidth, &pixelHeight);
    if (windowWidth > 0 && windowHeight > 0)
    {
        x *= double(pixelWidth) / windowWidth;
        y *= double(pixelHeight) / windowHeight;
    }
}

void GlfwEventAdapter::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods)
{
    GlfwEventAdapter& self = adapterOf(window);
    const int symbol = osgKeySymbol(key, mods);
    if (symbol == 0)
        return;
    self.queue().getCurrentEventState()->setModKeyMask(osgModKeyMask(mods));
    if (action == GLFW_RELEASE)
        self.queue().keyRelease(symbol);
    else // GLFW_PRESS or GLFW_REPEAT: OSG's windows repeat presses too
        self.queue().keyPress(symbol);
}

void GlfwEventAdapter::onMouseButton(GLFWwindow* window, int button, int action, int mods)
{
    GlfwEventAdapter& self = adapterOf(window);
    // OSG numbers buttons 1 left, 2 middle, 3 right; GLFW 0 left, 1 right, 2 middle.
    const unsigned osgButton = button == GLFW_MOUSE_BUTTON_LEFT     ? 1
                               : button == GLFW_MOUSE_BUTTON_MIDDLE ? 2
                               : button == GLFW_MOUSE_BUTTON_RIGHT  ? 3
                                                                    : unsigned(button + 1);
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    self.toPixels(x, y);
    self.queue().getCurrentEventState()->setModKeyMask(osgModKeyMask(mods));
    if (action == GLFW_PRESS)
        self.queue().mouseButtonPress(float(x), float(y), osgButton);
    else
        self.queue().mouseButtonRelease(float(x), float(y), osgButton);
}

void GlfwEventAdapter::onCursor(GLFWwindow* window, double x, double y)
{
    GlfwEventAdapter& self = adapterOf(window);
    self.toPixels(x, y);
    self.queue().mouseMotion(float(x), float(y));
}

void GlfwEventAdapter::onScroll(GLFWwindow* window, double /*dx*/, double dy)
{
    if (dy == 0.0)
        return;
    adapterOf(window).queue().mouseScroll(dy > 0.0 ? osgGA::GUIEventAdapter::SCROLL_UP
                                                   : osgGA::GUIEventAdapter::SCROLL_DOWN);
}

void GlfwEventAdapter::onFramebufferSize(GLFWwindow* window, int width, int height)
{
    if (width <= 0 || height <= 0)
        return; // minimised: keep the last size rather than a degenerate projection
    GlfwEventAdapter& self = adapterOf(window);
    // resized() moves the viewport and keeps the projection's aspect; the event tells the handlers.
    self._embedded->resized(0, 0, width, height);
    self.queue().windowResize(0, 0, width, height);
}
} // namespace osgVis::glfwapp
