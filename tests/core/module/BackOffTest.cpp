// SPDX-License-Identifier: MIT
// Do no harm: the governor keeps culling where it pays and backs off where it costs more than it
// saves, judged from frame times alone. Frame k's time reaches the governor at call k+1, as a
// renderer measures it.
#include <osgVis/core/module/BackOff.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace osgVis::core;

namespace
{
struct SimulatedRun
{
    unsigned chainFrames = 0;     // frames culled with the chain, over the last `tail` frames
    unsigned tail = 0;
    bool backedOff = false;
    std::uint32_t switches = 0;
};

// `cost(frame, usedChain)`: seconds that frame takes.
SimulatedRun simulate(BackOff& governor, unsigned frames, unsigned tail,
             const std::function<double(unsigned, bool)>& cost)
{
    SimulatedRun run;
    run.tail = tail;
    double previous = 0.0;
    for (unsigned frame = 0; frame < frames; ++frame)
    {
        const bool chain = governor.useChain(previous);
        previous = cost(frame, chain);
        if (frame >= frames - tail)
            run.chainFrames += chain;
    }
    run.backedOff = governor.backedOff();
    run.switches = governor.switches();
    return run;
}
} // namespace

TEST(BackOff, BacksOffWhereTheChainCostsMoreThanItSaves)
{
    BackOff governor;
    const SimulatedRun run = simulate(governor, 400, 128, [](unsigned, bool chain) { return chain ? 0.010 : 0.008; });
    EXPECT_TRUE(run.backedOff);
    EXPECT_EQ(run.switches, 1u);
    EXPECT_LE(run.chainFrames, 128u / 8u) << "only the probe blocks still try the chain";
    EXPECT_NEAR(governor.chainFrameMs(), 10.0, 1e-9);
    EXPECT_NEAR(governor.skipFrameMs(), 8.0, 1e-9);
}

TEST(BackOff, KeepsTheChainWhereItPays)
{
    BackOff governor;
    const SimulatedRun run = simulate(governor, 400, 128, [](unsigned, bool chain) { return chain ? 0.006 : 0.010; });
    EXPECT_FALSE(run.backedOff);
    EXPECT_EQ(run.switches, 0u);
    EXPECT_GE(run.chainFrames, 128u - 128u / 8u) << "at most one block in eight probes the renderer alone";
}

TEST(BackOff, DifferencesWithinTheMarginAndNoiseChangeNothing)
{
    BackOff governor;
    std::mt19937 random(3);
    std::uniform_real_distribution<double> jitter(0.98, 1.02);
    // The walk makes both choices four times slower and back, the chain 1 % faster throughout.
    const SimulatedRun run = simulate(governor, 4000, 512,
                             [&](unsigned frame, bool chain)
                             {
                                 const double scene = 0.005 * (2.5 + 1.5 * std::sin(frame * 0.01));
                                 return (chain ? 0.99 : 1.0) * scene * jitter(random);
                             });
    EXPECT_FALSE(run.backedOff);
    EXPECT_EQ(run.switches, 0u);
}

TEST(BackOff, ComesBackWhenTheChainPaysAgain)
{
    BackOff governor;
    // A small room first (the chain costs more), then a large hall where it saves a lot.
    const SimulatedRun run = simulate(governor, 1200, 128,
                             [](unsigned frame, bool chain)
                             {
                                 if (frame < 400)
                                     return chain ? 0.010 : 0.008;
                                 return chain ? 0.010 : 0.030;
                             });
    EXPECT_FALSE(run.backedOff);
    EXPECT_EQ(run.switches, 2u);
}

TEST(BackOff, ProbesGrowRareWhileTheAnswerIsClear)
{
    BackOff governor;
    // The chain halves the frame time: probes double their cycle up to 32 blocks of 8 frames.
    const SimulatedRun run = simulate(governor, 3000, 1024, [](unsigned, bool chain) { return chain ? 0.005 : 0.010; });
    EXPECT_FALSE(run.backedOff);
    EXPECT_LE(1024u - run.chainFrames, 1024u / (32u * 8u) * 8u + 8u) << "about one probe block in 32";
    EXPECT_GE(1024u - run.chainFrames, 8u) << "but it still probes";
}

TEST(BackOff, DisabledAlwaysCullsWithTheChain)
{
    BackOffOptions options;
    options.enabled = false;
    BackOff governor(options);
    const SimulatedRun run = simulate(governor, 200, 200, [](unsigned, bool chain) { return chain ? 0.1 : 0.001; });
    EXPECT_EQ(run.chainFrames, 200u);
    EXPECT_FALSE(run.backedOff);
}
