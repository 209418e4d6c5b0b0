// SPDX-License-Identifier: MIT
// osgvisbench's help: one section per topic, each subcommand's help its synopsis and its topics.
#include "BenchOptions.h"

#include <string>

namespace osgVis::bench
{
namespace
{
const char* sceneSynopsis()
{
    return "(--scene FILE | --generate office|city|floor|tetra|forest [--layout L] [--triangles N] [--seed S])\n"
           "        [--clusters on|off|N]";
}

const char* walkSynopsis()
{
    return "[--walk FILE|auto|random|orbit] [--save-walk FILE] [--views N] [--size WxH] [--cube | --fov 360]\n"
           "        [--modes osg,osg-oq,exact,frustum,frustum+octree,...] [--supersample K] [--backoff on|off]";
}

// The subcommands in a line each, for the help without one.
const char* subcommandList()
{
    return "\n"
           "Subcommands, each a run of its own with only its options (osgvisbench SUBCOMMAND --help):\n"
           "  run      the walk in every mode against the exact-visibility oracle (the default)\n"
           "  dynamic  the same while cars drive and buildings are dropped and deleted\n"
           "  paged    a paged database walked with OSG's DatabasePager\n"
           "  volume   the multifocal volume PVS of a box of eyes against the volume oracle\n"
           "  cells    the view cells of a multifocal .pvs against the volume oracle\n"
           "  dump     every module chain's visible sets per view, written out\n"
           "Without a subcommand every option below is taken, --dynamic, --paged, --volume, --volume-cells\n"
           "and --dump-visible choosing the run, as before the subcommands.\n";
}

// What the bench does.
const char* overview()
{
    return "\n"
           "Renders every mode over the same walk in one process and measures it against the\n"
           "exact-visibility oracle (docs/benchmark.md). A module chain is written with '+'; a name\n"
           "osgVis lacks loads the plugin osgvis_module_<name>.so from OSGVIS_MODULE_PATH or\n"
           "lib/osgvis-modules (docs/visapi.md).\n"
           "Default modes: osg,frustum,exact.\n";
}

// Which walk, and the views made of it.
const char* walkOptions()
{
    return "--walk: a walk file (docs/walk-format.md), auto (eyes at a person's height in the model's\n"
           "  free space, never inside solid geometry), random (300 views: those eyes jittered, each\n"
           "  looking in a random direction, seeded by --seed: views nobody tuned) or orbit (around\n"
           "  the model). Default: the walk\n"
           "  beside the scene, the generator's walk with --generate, else auto (an orbit when the\n"
           "  model has nowhere to stand).\n"
           "--save-walk FILE: write the walk followed (an automatic one, too) as a walk file, to edit\n"
           "  or replay with --walk FILE.\n"
           "--cube: every walk key becomes six 90-degree square views (HxH, H the walk's height),\n"
           "  the faces of a cube around the eye, so every metric covers the full sphere.\n";
}

// dump: the visible sets written out.
const char* dumpOptions()
{
    return "dump --dump-visible DIR (or --dump-visible DIR alone): instead of the benchmark, write DIR/<mode>.visible for every module-chain\n"
           "  mode: per view of the walk (after --views and --cube), the sorted canonical identities of\n"
           "  the objects the chain answers visible, culled on the scene as a VisibilityGroup extracts it\n"
           "  (glTF node path and primitive, \"n0/n3#p1\", for models read by osgVis's glTF plugin; object\n"
           "  ids otherwise). No rendering; osgvisrawgl writes the same files from its own loader\n"
           "  (docs/visapi.md, \"A renderer that is not OSG\").\n";
}

// The cull-only sweeps.
const char* sweepOptions()
{
    return "--speeds, --threads: also time each module-chain mode's cull alone (no rendering) with\n"
           "  the observer S times faster (every S-th walk key) under T TBB threads, and check that\n"
           "  every thread count gives the same visible sets. A missing list means speed 1 or\n"
           "  TBB's default thread count.\n"
           "--mask-deltas: also run every mode with a mask stage (mask, mask-approx, mask-distance,\n"
           "  e.g. frustum+mask) cull-only over the same views once per image-space shrinkage\n"
           "  Delta (frame pixels; the mode's own options otherwise) and report the fraction of\n"
           "  critical frames and their reasons, the median/p99 ms of each step of a critical\n"
           "  frame (select, rasterize, pyramid, mark), the median cull ms of critical and other\n"
           "  frames, and the drawn fraction. The mask stages' top eye speed V (MaskOptions::\n"
           "  maxEyeSpeed) is set to the observer's measured top speed over the swept frames (an\n"
           "  application knows its camera's top speed), 1.01 x max |eye step| / time step.\n"
           "--mask-slowdown K: the Delta sweep's observer walks the same path K times slower\n"
           "  (default 1): K-1 frames between consecutive views, the eye moved linearly with the\n"
           "  earlier view's orientation, at the views' own time step, so consecutive frames are\n"
           "  close and the masks' temporal coherence shows. At most 200000 frames (views x K).\n"
           "--cull-only: run just these sweeps (no oracle, no GL).\n";
}

// dynamic: the scene changing during the walk.
const char* dynamicOptions()
{
    return "dynamic (or --dynamic): a dynamic walk (osg and module-chain modes): 12 cars drive along the walk's\n"
           "  streets every frame, 3 buildings are dropped on existing ones at 1/4 and at 1/2 of\n"
           "  the views, 3 are deleted at 1/3 and at 2/3 (seeded by --seed); the oracle renders\n"
           "  every frame's scene, and the number of changes applied is printed.\n";
}

// paged: a paged database.
const char* pagedOptions()
{
    return "paged (or --paged): the scene is a paged database (osgvisgen --paged DIR: --scene DIR/root.osgb, walk\n"
           "  DIR/root.walk) walked with OSG's DatabasePager running, frames back to back; osg and\n"
           "  module-chain modes, each from a fresh read of the root. Per mode: tile files requested,\n"
           "  tiles loaded and expired, MB read, peak resident tiles, peak heap growth, pop-in (frames,\n"
           "  objects and pixels the oracle sees on the fully loaded database whose tile was not loaded\n"
           "  yet), false-invisible among loaded tiles' objects, fps and its ratio to osg\n"
           "  (docs/paging.md). --scene DIR/x.pvs: a cell-portal bake of the whole database\n"
           "  (osgvispvs DIR/root.osgb -o DIR/x.pvs), which cellportal modes use for every load\n"
           "  state; the bench pages the root file it names.\n"
           "--paging-requests N: of the visible tiles not loaded yet that a nearer one covers on\n"
           "  screen, a view asks for N per frame, nearest first (default 0: every visible one, as OSG\n"
           "  does). --paging-keep N: a loaded tile hidden for at most N\n"
           "  frames keeps its time stamps fresh (default 120), within OSG_MAX_PAGEDLOD.\n"
           "  --paging-keep-mb M: and within M MB of their geometry's arrays (default 0: no limit).\n"
           "  --paging-prefetch N: tiles the eye will pass through within N frames at its last step are\n"
           "  requested ahead at a lower priority (default 0: off), and with a baked cellportal\n"
           "  PVS the tiles some eye along that path may see.\n";
}

// The threading table.
const char* threadingOptions()
{
    return "--threading M1,M2 / --async on,off: also render every osg and module-chain mode under each\n"
           "  OSG threading model (SingleThreaded, CullDrawThreadPerContext, DrawThreadPerContext,\n"
           "  CullThreadPerCameraDrawThreadPerContext; default SingleThreaded) with asynchronous\n"
           "  visibility on and/or off (default off), and print the threading table: false-invisible,\n"
           "  drawn fraction, the cull thread's median ms in osgVis and OSG's cull ms, frames that fell\n"
           "  back to a synchronous cull, fps and its ratio to the same mode SingleThreaded, and for\n"
           "  synchronous rows the views whose drawn set differs from the main table's pass. Set\n"
           "  LP_NUM_THREADS (Mesa) when timing: llvmpipe's threads compete for the same cores.\n"
           "--async-lookahead N: frames of predicted eye path an async region covers (default 4).\n"
           "--async-region X,Y,Z: an async region is at least this box around the eye (a bake\n"
           "  cell's size, for multifocal regions); default: the path alone.\n";
}

// volume: the multifocal volume PVS against the volume oracle.
const char* volumeOptions()
{
    return "volume --volume X0,Y0,Z0,X1,Y1,Z1 | paper (or --volume alone): instead of the walk, the multifocal volume PVS of that\n"
           "  box of eyes (paper: the view volume of the generated forest's layout, docs/scenes.md),\n"
           "  timed (median of --volume-repeat N, default 3), against the volume oracle (eyes at the\n"
           "  box's 8 corners, 6 face centres and --volume-eyes N (default 48) random points, six\n"
           "  --volume-face N pixel (default 512) cube faces each, objects and triangles). Prints\n"
           "  objects and triangles kept, culled, facing away from every eye, and missing (exit\n"
           "  status 1 when any is missing), and the efficacy on the triangles not facing away.\n"
           "  --plane-resolution N (default 100) and --planes N (default 7) set the planes.\n";
}

// cells: the baked cells of a .pvs against the volume oracle.
const char* cellsOptions()
{
    return "cells --volume-cells N (or --volume-cells alone): with --scene FILE.pvs baked by osgvispvs --method multifocal, N of its\n"
           "  view cells (evenly spread over them) against the volume oracle (objects): objects the\n"
           "  oracle sees that a cell's PVS lacks (exit status 1 when any), and the triangles of the\n"
           "  PVS's objects over those of the objects seen, per cell and on average.\n";
}

// Where the figures go.
const char* jsonOption()
{
    return "--json OUT.json: also write the run's figures as JSON (docs/benchmark.md).\n";
}

// The report, the oracle cache and --explain.
const char* reportOptions()
{
    return "--report DIR: also write DIR/index.html, one self-contained page (inline SVG, nothing\n"
           "  fetched): the table, per-view plots of drawn triangles for every mode against exact and of\n"
           "  cull ms, false-invisible markers, the progressive and threading tables, and N side-by-side\n"
           "  pictures DIR/view-NNNN.png (--pictures N, default 6, 0 for none) of views spread over the\n"
           "  walk: osg's frame | the best mode's frame | a top-down map of what the best mode drew\n"
           "  (green), culled in the frustum (red), left outside it (grey), and the frustum (yellow).\n"
           "  The best mode is the conservative module chain with the highest fps.\n"
           "--oracle-cache DIR: keep the oracle's exact sets of the rendered walk in DIR, one file per\n"
           "  model geometry, views, size and --supersample, and take them from there when a later run\n"
           "  has the same (then the oracle renders nothing). Not for --dynamic or --paged runs.\n"
           "--explain: also say why culling does or does not work on the model: the objects that\n"
           "  are no occluder, by reason (transparent, alpha test, polygon mode, no depth write, under\n"
           "  LOD/Switch, dynamic, degenerate, too small, ...), the occluder polygons the object-space\n"
           "  methods get, objects whose bounds span more than half the model, and the objects the\n"
           "  best mode never culled although hidden, largest first, with the likeliest reason.\n";
}

// How the modes cull: clusters, back-off.
const char* cullingOptions()
{
    return "--clusters on|off|N: split drawables of at least N triangles (on: the default, 4096) into\n"
           "  clusters culled as objects (docs/clusters.md); off keeps every drawable whole. Sets\n"
           "  OSGVIS_CLUSTER_THRESHOLD for every extraction of the run. With clusters the oracle's\n"
           "  objects are narrowed to clusters by a triangle-ID render.\n"
           "--backoff on: measure the modes as an application with do no harm gets them: each\n"
           "  VisibilityGroup times frames with and without its chain and skips the chain where it\n"
           "  costs more than it saves (core::BackOff; timing-dependent, so off by default: each\n"
           "  method is measured alone).\n";
}

// What every rendered mode is measured on, and the exit status.
const char* exitStatus()
{
    return "Every rendered mode also gets its mis-drawn pixels: pixels of the oracle's exact image\n"
           "  (display resolution) showing an object the mode culled (where the oracle counts\n"
           "  pixels per object). Approximate modes report false-invisible objects, never fail.\n"
           "Exit status: 0 ok, 1 a conservative mode culled a visible object, gave different\n"
           "visible sets at different thread counts or threading models, or the run failed;\n"
           "2 bad command line.\n";
}

// The synopsis of a subcommand: its name and its options.
std::string synopsis(BenchCommand command)
{
    const std::string scene = sceneSynopsis(), walk = walkSynopsis();
    switch (command)
    {
    case BenchCommand::Run:
        return "usage: osgvisbench run " + scene + "\n        " + walk +
               "\n        [--speeds 1,2,4,8,16] [--threads 1,2] [--mask-deltas 0,1,2,4,8] [--mask-slowdown K]"
               " [--cull-only]\n        [--threading MODEL,...] [--async on|off|on,off] [--async-lookahead N]"
               " [--async-region X,Y,Z]\n        [--json OUT.json] [--report DIR [--pictures N]] [--explain]"
               " [--oracle-cache DIR] [--help]\n";
    case BenchCommand::Dynamic:
        return "usage: osgvisbench dynamic " + scene + "\n        " + walk + "\n        [--json OUT.json] [--help]\n";
    case BenchCommand::Paged:
        return "usage: osgvisbench paged --scene DIR/root.osgb|FILE.pvs [--clusters on|off|N]\n        " + walk +
               "\n        [--paging-requests N] [--paging-keep N] [--paging-keep-mb M] [--paging-prefetch N]"
               " [--json OUT.json] [--help]\n";
    case BenchCommand::Volume:
        return "usage: osgvisbench volume " + scene +
               "\n        --volume X0,Y0,Z0,X1,Y1,Z1|paper [--plane-resolution N] [--planes N] [--volume-face N]"
               "\n        [--volume-eyes N] [--volume-repeat N] [--json OUT.json] [--help]\n";
    case BenchCommand::Cells:
        return "usage: osgvisbench cells --scene FILE.pvs --volume-cells N [--volume-face N] [--volume-eyes N]"
               "\n        [--json OUT.json] [--help]\n";
    case BenchCommand::Dump:
        return "usage: osgvisbench dump " + scene + "\n        " + walk + "\n        --dump-visible DIR [--help]\n";
    }
    return {};
}

// Every option, as before the subcommands.
std::string everyOption()
{
    return "usage: osgvisbench [SUBCOMMAND] " + std::string(sceneSynopsis()) + "\n        " + walkSynopsis() +
           "\n        [--speeds 1,2,4,8,16] [--threads 1,2] [--mask-deltas 0,1,2,4,8] [--mask-slowdown K] [--cull-only]"
           "\n        [--dynamic] [--paged [--paging-requests N] [--paging-keep N] [--paging-keep-mb M]"
           " [--paging-prefetch N]]"
           "\n        [--threading MODEL,...] [--async on|off|on,off] [--async-lookahead N] [--async-region X,Y,Z]"
           "\n        [--volume X0,Y0,Z0,X1,Y1,Z1|paper [--plane-resolution N] [--planes N]"
           "\n         [--volume-face N] [--volume-eyes N] [--volume-repeat N]] [--volume-cells N]"
           "\n        [--json OUT.json] [--report DIR [--pictures N]] [--explain] [--oracle-cache DIR]"
           "\n        [--dump-visible DIR] [--help]\n";
}
} // namespace

std::string benchUsage()
{
    return everyOption() + subcommandList() + overview() + walkOptions() + dumpOptions() + sweepOptions() +
           dynamicOptions() + pagedOptions() + threadingOptions() + volumeOptions() + cellsOptions() +
           jsonOption() + reportOptions() + cullingOptions() + exitStatus();
}

std::string benchUsage(const BenchOptions& options)
{
    if (!options.commandGiven)
        return benchUsage();
    const std::string head = synopsis(options.command);
    switch (options.command)
    {
    case BenchCommand::Run:
        return head + overview() + walkOptions() + sweepOptions() + threadingOptions() + jsonOption() +
               reportOptions() + cullingOptions() + exitStatus();
    case BenchCommand::Dynamic:
        return head + overview() + dynamicOptions() + walkOptions() + jsonOption() + cullingOptions() + exitStatus();
    case BenchCommand::Paged:
        return head + overview() + pagedOptions() + walkOptions() + jsonOption() + cullingOptions() + exitStatus();
    case BenchCommand::Volume:
        return head + "\n" + volumeOptions() + jsonOption() + cullingOptions();
    case BenchCommand::Cells:
        return head + "\n" + cellsOptions() + jsonOption();
    case BenchCommand::Dump:
        return head + overview() + dumpOptions() + walkOptions() + cullingOptions();
    }
    return head;
}
} // namespace osgVis::bench
