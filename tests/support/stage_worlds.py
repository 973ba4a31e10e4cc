"""World files for the simulator's tests, and where stage_ros's own examples are when fetched."""

from __future__ import annotations

from pathlib import Path

#: A 10 m square room (walls 0.2 m thick, inner faces at ±4.9 m) and one robot at the centre,
#: facing +x, with a 181-beam laser over 180° reaching 8 m.
ROOM = """\
# a room for tests
resolution 0.02
interval_sim 100

define wall model ( color "gray30" )
define hokuyo ranger ( sensor ( range [ 0.05 8.0 ] fov 180 samples 181 ) )
define bot position (
  size [ 0.3 0.3 0.2 ]
  drive "diff"
  hokuyo ( pose [ 0 0 0 0 ] )
)

wall ( name "east"  pose [  5 0 0 0 ] size [ 0.2 10.2 0.5 ] )
wall ( name "west"  pose [ -5 0 0 0 ] size [ 0.2 10.2 0.5 ] )
wall ( name "north" pose [ 0  5 0 0 ] size [ 10.2 0.2 0.5 ] )
wall ( name "south" pose [ 0 -5 0 0 ] size [ 10.2 0.2 0.5 ] )
"""


def room(*robots: str, extra: str = "") -> str:
    """The room with robots (``bot ( ... )`` bodies), one at the centre if none is given."""
    bodies = robots or ('pose [ 0 0 0 0 ] name "r0"',)
    return ROOM + extra + "".join(f"bot ( {body} )\n" for body in bodies)


#: Where a fetched copy of stage_ros (a git directory) is looked for, unless
#: ``ROSX_STAGE_ROS_GIT`` names one.
STAGE_ROS_GIT = Path("/work/.mirror/ros-simulation+stage_ros/repo")
#: stage_ros's example worlds and the bitmap they load.
STAGE_ROS_WORLDS = (
    "willow-erratic.world",
    "willow-four-erratics.world",
    "willow-four-erratics-multisensor.world",
    "intense.world",
    "erratic-inc.world",
    "willow-full.pgm",
)


def export_stage_ros_worlds(into: Path) -> Path | None:
    """stage_ros's example worlds written into ``into`` from a fetched copy of its
    repository, or None without one (they are read, never kept in rosx)."""
    import os
    import subprocess

    git = Path(os.environ.get("ROSX_STAGE_ROS_GIT", str(STAGE_ROS_GIT)))
    if not git.is_dir():
        return None
    for name in STAGE_ROS_WORLDS:
        shown = subprocess.run(
            ["git", "-C", str(git), "show", f"HEAD:world/{name}"],
            capture_output=True,
            check=False,
        )
        if shown.returncode != 0:
            return None
        (into / name).write_bytes(shown.stdout)
    return into
