// SPDX-License-Identifier: MIT
#pragma once
// First-person camera for walking through a scene: keys move the eye, a left-button drag turns the
// head, `p` plays the walk back by its own time stamps and `r` records the eye path as a walk.
// World up is +z (OSG's and the generator's convention).
#include <osgVis/core/scene/Walk.h>

#include <osgGA/CameraManipulator>

#include <set>
#include <string>

namespace osgVis::viewer
{
// The walk's viewpoint at time `time` (linear between keys, clamped to the ends). Walks whose keys
// share one time stamp are played at one key per 1/30 s.
core::WalkKey sampleWalk(const core::Walk& walk, double time);
// Time stamp of the walk's last key in sampleWalk's time.
double walkDuration(const core::Walk& walk);

class WalkManipulator : public osgGA::CameraManipulator
{
public:
    // `speed` in scene units per second; `recordPath` empty disables recording.
    WalkManipulator(const core::Walk& walk, double speed, const std::string& recordPath);

    const char* className() const override { return "WalkManipulator"; }

    void setByMatrix(const osg::Matrixd& matrix) override;
    void setByInverseMatrix(const osg::Matrixd& matrix) override { setByMatrix(osg::Matrixd::inverse(matrix)); }
    osg::Matrixd getMatrix() const override { return osg::Matrixd::inverse(getInverseMatrix()); }
    osg::Matrixd getInverseMatrix() const override;

    void home(double currentTime) override;
    void home(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter& aa) override;
    void getUsage(osg::ApplicationUsage& usage) const override;

    bool playing() const { return _playing; }
    bool recording() const { return _recording; }

private:
    void setFromKey(const core::WalkKey& key);
    osg::Vec3d lookDirection() const;
    void advance(double seconds);
    void togglePlayback(double now);
    void toggleRecording(double now, osgGA::GUIActionAdapter& aa);
    void recordKey(double now);

    core::Walk _walk;
    std::string _recordPath;
    double _speed;

    osg::Vec3d _eye;
    double _yaw = 0.0;   // radians about +z, 0 looks along +x
    double _pitch = 0.0; // radians above the horizon
    std::set<int> _heldKeys;
    bool _fast = false;
    double _lastFrameTime = -1.0;
    float _dragX = 0.0f, _dragY = 0.0f;

    bool _playing = false;
    double _playStart = 0.0;
    core::WalkKey _playKey;

    bool _recording = false;
    double _recordStart = 0.0;
    core::Walk _recorded;
};
} // namespace osgVis::viewer
