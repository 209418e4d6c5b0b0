// SPDX-License-Identifier: MIT
#include "WalkManipulator.h"

#include <CameraSetup.h>

#include <osg/ApplicationUsage>
#include <osgViewer/View>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>

namespace osgVis::viewer
{
namespace
{
constexpr double SecondsPerUntimedKey = 1.0 / 30.0;
constexpr double RecordInterval = 1.0 / 30.0;
constexpr double MaxPitch = 1.55; // just under 90 degrees: lookAt needs a view direction off the up axis
constexpr double FastFactor = 4.0;
const osg::Vec3d WorldUp(0.0, 0.0, 1.0);

bool untimed(const core::Walk& walk)
{
    return walk.keys.size() > 1 && walk.keys.back().time <= walk.keys.front().time;
}

int normalizedKey(int key)
{
    return (key >= 'A' && key <= 'Z') ? std::tolower(key) : key;
}
} // namespace

double walkDuration(const core::Walk& walk)
{
    if (walk.keys.empty())
        return 0.0;
    if (untimed(walk))
        return SecondsPerUntimedKey * double(walk.keys.size() - 1);
    return walk.keys.back().time - walk.keys.front().time;
}

core::WalkKey sampleWalk(const core::Walk& walk, double time)
{
    if (walk.keys.empty())
        return core::WalkKey();
    const std::vector<core::WalkKey>& keys = walk.keys;
    if (untimed(walk))
    {
        const std::size_t index = std::min(keys.size() - 1, std::size_t(std::max(0.0, time / SecondsPerUntimedKey)));
        return keys[index];
    }
    const double t = keys.front().time + time;
    auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                  [](double value, const core::WalkKey& key) { return value < key.time; });
    if (after == keys.begin())
        return keys.front();
    if (after == keys.end())
        return keys.back();
    const core::WalkKey& a = *(after - 1);
    const core::WalkKey& b = *after;
    const double span = b.time - a.time;
    const double f = span > 0.0 ? (t - a.time) / span : 0.0;
    core::WalkKey key;
    key.time = t;
    key.eye = glm::mix(a.eye, b.eye, f);
    key.center = glm::mix(a.center, b.center, f);
    key.up = glm::mix(a.up, b.up, f);
    return key;
}

WalkManipulator::WalkManipulator(const core::Walk& walk, double speed, const std::string& recordPath)
    : _walk(walk), _recordPath(recordPath), _speed(speed)
{
    if (!_walk.keys.empty())
        setFromKey(_walk.keys.front());
}

void WalkManipulator::setFromKey(const core::WalkKey& key)
{
    _eye.set(key.eye.x, key.eye.y, key.eye.z);
    const core::Vec3 d = key.center - key.eye;
    const double length = glm::length(d);
    if (length <= 0.0)
        return;
    _yaw = std::atan2(d.y, d.x);
    _pitch = std::clamp(std::asin(std::clamp(d.z / length, -1.0, 1.0)), -MaxPitch, MaxPitch);
}

void WalkManipulator::setByMatrix(const osg::Matrixd& matrix)
{
    // The camera looks down its local -z axis, whose world direction is the matrix's third row negated.
    const osg::Vec3d eye = matrix.getTrans();
    const osg::Vec3d direction(-matrix(2, 0), -matrix(2, 1), -matrix(2, 2));
    core::WalkKey key;
    key.eye = core::Vec3(eye.x(), eye.y(), eye.z());
    key.center = key.eye + core::Vec3(direction.x(), direction.y(), direction.z());
    setFromKey(key);
}

osg::Vec3d WalkManipulator::lookDirection() const
{
    return osg::Vec3d(std::cos(_pitch) * std::cos(_yaw), std::cos(_pitch) * std::sin(_yaw), std::sin(_pitch));
}

osg::Matrixd WalkManipulator::getInverseMatrix() const
{
    if (_playing)
        return apps::walkViewMatrix(_playKey);
    return osg::Matrixd::lookAt(_eye, _eye + lookDirection(), WorldUp);
}

void WalkManipulator::home(double)
{
    _playing = false;
    if (!_walk.keys.empty())
        setFromKey(_walk.keys.front());
}

void WalkManipulator::home(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    home(ea.getTime());
    aa.requestRedraw();
}

void WalkManipulator::advance(double seconds)
{
    osg::Vec3d forward = lookDirection();
    osg::Vec3d right = forward ^ WorldUp;
    right.normalize();
    osg::Vec3d move;
    for (int key : _heldKeys)
    {
        switch (key)
        {
        case 'w':
        case osgGA::GUIEventAdapter::KEY_Up:
            move += forward;
            break;
        case 's':
        case osgGA::GUIEventAdapter::KEY_Down:
            move -= forward;
            break;
        case 'd':
        case osgGA::GUIEventAdapter::KEY_Right:
            move += right;
            break;
        case 'a':
        case osgGA::GUIEventAdapter::KEY_Left:
            move -= right;
            break;
        case 'e':
        case osgGA::GUIEventAdapter::KEY_Page_Up:
            move += WorldUp;
            break;
        case 'q':
        case osgGA::GUIEventAdapter::KEY_Page_Down:
            move -= WorldUp;
            break;
        default:
            break;
        }
    }
    if (move.length2() > 0.0)
        _eye += move * (_speed * (_fast ? FastFactor : 1.0) * seconds / move.length());
}

void WalkManipulator::togglePlayback(double now)
{
    if (_playing)
    {
        _playing = false;
        setFromKey(_playKey);
        std::cout << "osgvisviewer: walk stopped" << std::endl;
        return;
    }
    if (_walk.keys.empty())
        return;
    _playing = true;
    _playStart = now;
    _playKey = _walk.keys.front();
    std::cout << "osgvisviewer: playing the walk (" << _walk.keys.size() << " views, " << walkDuration(_walk)
              << " s); p stops" << std::endl;
}

void WalkManipulator::recordKey(double now)
{
    const double t = now - _recordStart;
    if (!_recorded.keys.empty() && t - _recorded.keys.back().time < RecordInterval)
        return;
    core::WalkKey key;
    if (_playing)
    {
        key = _playKey;
    }
    else
    {
        const osg::Vec3d center = _eye + lookDirection();
        key.eye = core::Vec3(_eye.x(), _eye.y(), _eye.z());
        key.center = core::Vec3(center.x(), center.y(), center.z());
        key.up = core::Vec3(WorldUp.x(), WorldUp.y(), WorldUp.z());
    }
    key.time = t;
    _recorded.keys.push_back(key);
}

void WalkManipulator::toggleRecording(double now, osgGA::GUIActionAdapter& aa)
{
    if (_recordPath.empty())
    {
        std::cout << "osgvisviewer: start the viewer with --record FILE to record the eye path" << std::endl;
        return;
    }
    if (!_recording)
    {
        _recording = true;
        _recordStart = now;
        _recorded = core::Walk();
        _recorded.projection = _walk.projection;
        recordKey(now);
        std::cout << "osgvisviewer: recording the eye path; r stops and saves to " << _recordPath << std::endl;
        return;
    }
    _recording = false;
    if (auto* view = dynamic_cast<osgViewer::View*>(&aa); view && view->getCamera()->getViewport())
    {
        _recorded.width = unsigned(view->getCamera()->getViewport()->width());
        _recorded.height = unsigned(view->getCamera()->getViewport()->height());
    }
    try
    {
        _recorded.save(_recordPath);
        std::cout << "osgvisviewer: saved " << _recorded.keys.size() << " views to " << _recordPath << std::endl;
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisviewer: cannot save the recorded walk: " << e.what() << "\n";
    }
}

bool WalkManipulator::handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa)
{
    _fast = (ea.getModKeyMask() & osgGA::GUIEventAdapter::MODKEY_SHIFT) != 0;
    switch (ea.getEventType())
    {
    case osgGA::GUIEventAdapter::FRAME:
    {
        const double now = ea.getTime();
        const double seconds = _lastFrameTime < 0.0 ? 0.0 : std::min(now - _lastFrameTime, 0.25);
        _lastFrameTime = now;
        if (_playing)
        {
            const double t = now - _playStart;
            _playKey = sampleWalk(_walk, t);
            if (t > walkDuration(_walk))
                togglePlayback(now);
        }
        else
        {
            advance(seconds);
        }
        if (_recording)
            recordKey(now);
        return false;
    }
    case osgGA::GUIEventAdapter::KEYDOWN:
    {
        const int key = normalizedKey(ea.getKey());
        if (key == 'p')
        {
            togglePlayback(ea.getTime());
            return true;
        }
        if (key == 'r')
        {
            toggleRecording(ea.getTime(), aa);
            return true;
        }
        if (key == osgGA::GUIEventAdapter::KEY_Space)
        {
            home(ea, aa);
            return true;
        }
        static const int movementKeys[] = {'w', 'a', 's', 'd', 'q', 'e',
                                           osgGA::GUIEventAdapter::KEY_Up, osgGA::GUIEventAdapter::KEY_Down,
                                           osgGA::GUIEventAdapter::KEY_Left, osgGA::GUIEventAdapter::KEY_Right,
                                           osgGA::GUIEventAdapter::KEY_Page_Up, osgGA::GUIEventAdapter::KEY_Page_Down};
        if (std::find(std::begin(movementKeys), std::end(movementKeys), key) == std::end(movementKeys))
            return false;
        if (_playing)
            togglePlayback(ea.getTime());
        _heldKeys.insert(key);
        return true;
    }
    case osgGA::GUIEventAdapter::KEYUP:
        return _heldKeys.erase(normalizedKey(ea.getKey())) > 0;
    case osgGA::GUIEventAdapter::PUSH:
        _dragX = ea.getXnormalized();
        _dragY = ea.getYnormalized();
        return false;
    case osgGA::GUIEventAdapter::DRAG:
    {
        if (!(ea.getButtonMask() & osgGA::GUIEventAdapter::LEFT_MOUSE_BUTTON))
            return false;
        if (_playing)
            togglePlayback(ea.getTime());
        // A drag across the whole window turns the head by 180 degrees.
        _yaw -= (ea.getXnormalized() - _dragX) * osg::PI_2;
        _pitch = std::clamp(_pitch + (ea.getYnormalized() - _dragY) * osg::PI_4, -MaxPitch, MaxPitch);
        _dragX = ea.getXnormalized();
        _dragY = ea.getYnormalized();
        return true;
    }
    case osgGA::GUIEventAdapter::SCROLL:
        _speed *= ea.getScrollingMotion() == osgGA::GUIEventAdapter::SCROLL_UP ? 1.25 : 0.8;
        std::cout << "osgvisviewer: speed " << _speed << " units/s" << std::endl;
        return true;
    default:
        return false;
    }
}

void WalkManipulator::getUsage(osg::ApplicationUsage& usage) const
{
    usage.addKeyboardMouseBinding("w a s d / arrows", "Walk forward, left, back, right (shift: faster)");
    usage.addKeyboardMouseBinding("q e / Page Down, Page Up", "Move down, up");
    usage.addKeyboardMouseBinding("Left mouse drag", "Look around");
    usage.addKeyboardMouseBinding("Mouse wheel", "Change the walking speed");
    usage.addKeyboardMouseBinding("p", "Play / stop the walk");
    usage.addKeyboardMouseBinding("r", "Start / stop recording the eye path (--record FILE)");
    usage.addKeyboardMouseBinding("Space", "Back to the walk's first view");
}
} // namespace osgVis::viewer
