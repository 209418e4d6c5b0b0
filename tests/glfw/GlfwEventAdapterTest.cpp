// SPDX-License-Identifier: MIT
// The GLFW → OSG event adapter of osgvisglfw, compiled in: its key and modifier tables, and that
// each GLFW callback it installs puts the matching event in the embedded window's queue. The
// callbacks are called directly (read back with glfwSet*Callback), since no tool here synthesises
// X input.
#include "GlfwEventAdapter.h"

#include "AppProcess.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <gtest/gtest.h>

using osgGA::GUIEventAdapter;
using osgVis::glfwapp::GlfwEventAdapter;
using osgVis::glfwapp::osgKeySymbol;
using osgVis::glfwapp::osgModKeyMask;

TEST(GlfwEventAdapter, MapsKeysToOsgSymbols)
{
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_A, 0), 'a');
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_Z, GLFW_MOD_SHIFT), 'Z');
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_SPACE, 0), ' ');
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_1, 0), '1');
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_ESCAPE, 0), GUIEventAdapter::KEY_Escape);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_F5, 0), GUIEventAdapter::KEY_F5);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_F12, 0), GUIEventAdapter::KEY_F12);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_KP_3, 0), GUIEventAdapter::KEY_KP_3);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_PAGE_DOWN, 0), GUIEventAdapter::KEY_Page_Down);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_RIGHT_CONTROL, 0), GUIEventAdapter::KEY_Control_R);
    EXPECT_EQ(osgKeySymbol(GLFW_KEY_MENU, 0), 0);
}

TEST(GlfwEventAdapter, MapsModifiers)
{
    EXPECT_EQ(osgModKeyMask(0), 0);
    EXPECT_EQ(osgModKeyMask(GLFW_MOD_SHIFT | GLFW_MOD_ALT),
              GUIEventAdapter::MODKEY_SHIFT | GUIEventAdapter::MODKEY_ALT);
    EXPECT_EQ(osgModKeyMask(GLFW_MOD_CONTROL | GLFW_MOD_SUPER),
              GUIEventAdapter::MODKEY_CTRL | GUIEventAdapter::MODKEY_SUPER);
}

TEST(GlfwEventAdapter, ForwardsEachCallbackToTheEventQueue)
{
    if (!osgVis::test::haveDisplay())
        GTEST_SKIP() << "needs an X display (run under scripts/with-display.sh)";
    ASSERT_TRUE(glfwInit());
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(100, 80, "adapter test", nullptr, nullptr);
    ASSERT_NE(window, nullptr);
    osg::ref_ptr<osgViewer::GraphicsWindowEmbedded> embedded = new osgViewer::GraphicsWindowEmbedded(0, 0, 100, 80);
    {
        GlfwEventAdapter adapter(window, embedded.get());
        // Setting a callback returns the one installed before: the adapter's.
        const GLFWkeyfun key = glfwSetKeyCallback(window, nullptr);
        const GLFWmousebuttonfun button = glfwSetMouseButtonCallback(window, nullptr);
        const GLFWcursorposfun cursor = glfwSetCursorPosCallback(window, nullptr);
        const GLFWscrollfun scroll = glfwSetScrollCallback(window, nullptr);
        const GLFWframebuffersizefun size = glfwSetFramebufferSizeCallback(window, nullptr);
        ASSERT_TRUE(key && button && cursor && scroll && size);

        key(window, GLFW_KEY_S, 0, GLFW_PRESS, GLFW_MOD_CONTROL);
        key(window, GLFW_KEY_S, 0, GLFW_RELEASE, 0);
        key(window, GLFW_KEY_MENU, 0, GLFW_PRESS, 0); // no OSG symbol: dropped
        button(window, GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 0);
        cursor(window, 10.0, 20.0);
        button(window, GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 0);
        scroll(window, 0.0, -1.0);
        size(window, 60, 40);

        osgGA::EventQueue::Events events;
        embedded->getEventQueue()->takeEvents(events);
        std::vector<osg::ref_ptr<GUIEventAdapter>> queued;
        for (const auto& event : events)
            queued.push_back(event->asGUIEventAdapter());
        ASSERT_EQ(queued.size(), 7u);
        EXPECT_EQ(queued[0]->getEventType(), GUIEventAdapter::KEYDOWN);
        EXPECT_EQ(queued[0]->getKey(), 's');
        EXPECT_EQ(queued[0]->getModKeyMask(), int(GUIEventAdapter::MODKEY_CTRL));
        EXPECT_EQ(queued[1]->getEventType(), GUIEventAdapter::KEYUP);
        EXPECT_EQ(queued[2]->getEventType(), GUIEventAdapter::PUSH);
        EXPECT_EQ(queued[2]->getButton(), int(GUIEventAdapter::RIGHT_MOUSE_BUTTON));
        EXPECT_EQ(queued[3]->getEventType(), GUIEventAdapter::DRAG); // a button is held
        EXPECT_EQ(queued[3]->getX(), 10.f);
        EXPECT_EQ(queued[3]->getY(), 20.f);
        EXPECT_EQ(queued[4]->getEventType(), GUIEventAdapter::RELEASE);
        EXPECT_EQ(queued[5]->getEventType(), GUIEventAdapter::SCROLL);
        EXPECT_EQ(queued[5]->getScrollingMotion(), GUIEventAdapter::SCROLL_DOWN);
        EXPECT_EQ(queued[6]->getEventType(), GUIEventAdapter::RESIZE);
        EXPECT_EQ(queued[6]->getWindowWidth(), 60);
        EXPECT_EQ(queued[6]->getWindowHeight(), 40);
        EXPECT_EQ(embedded->getTraits()->width, 60);
        EXPECT_EQ(embedded->getTraits()->height, 40);
    }
    EXPECT_EQ(glfwSetKeyCallback(window, nullptr), nullptr) << "the adapter removes its callbacks";
    glfwDestroyWindow(window);
    glfwTerminate();
}
