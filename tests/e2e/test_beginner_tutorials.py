"""The wiki's ROS 1 beginner tutorials (ROS/Tutorials 1-19, the two C++ ones aside), walked as a
new user types them: bash with ``eval "$(rosx shell-init bash)"``, a fresh HOME with
``~/catkin_ws``, the commands as the tutorials print them. One test walks them in order (each
tutorial builds on the ones before); where Debian's ROS 1 tools are installed, rospack and roswtf
answer the same questions over the same folders and must print the same.

Not walked here: the keyboard (turtle_teleop_key) and the terminal UIs (rqt_graph, rqt_plot,
rqt_console, rqt_logger_level), which have their own tests (tests/tui); ``roscd roscpp/cmake``
and ``roscd rosmaster`` (rosx ships neither folder); the C++ tutorials (11, 14).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
import textwrap
from collections.abc import Iterator
from pathlib import Path

import pytest

from rosx.workspace.environment import ROS_ETC_DIR, ROS_ROOT, SHARE
from rosx_commands.main import TOOLS
from tests.support.cli import clean_environ
from tests.support.launchfiles import TURTLEMIMIC
from tests.support.procs import free_port, port_open, stop, wait_for
from tests.support.ros1 import ROS1

DEBIAN_ROSPACK = shutil.which("rospack", path="/usr/bin")

TALKER = """\
#!/usr/bin/env python
# license removed for brevity
import rospy
from std_msgs.msg import String

def talker():
    pub = rospy.Publisher('chatter', String, queue_size=10)
    rospy.init_node('talker', anonymous=True)
    rate = rospy.Rate(10) # 10hz
    while not rospy.is_shutdown():
        hello_str = "hello world %s" % rospy.get_time()
        rospy.loginfo(hello_str)
        pub.publish(hello_str)
        rate.sleep()

if __name__ == '__main__':
    try:
        talker()
    except rospy.ROSInterruptException:
        pass
"""

LISTENER = """\
#!/usr/bin/env python
import rospy
from std_msgs.msg import String

def callback(data):
    rospy.loginfo(rospy.get_caller_id() + "I heard %s", data.data)

def listener():
    rospy.init_node('listener', anonymous=True)
    rospy.Subscriber("chatter", String, callback)
    rospy.spin()

if __name__ == '__main__':
    listener()
"""

SERVER = """\
#!/usr/bin/env python
from __future__ import print_function

from beginner_tutorials.srv import AddTwoInts,AddTwoIntsResponse
import rospy

def handle_add_two_ints(req):
    print("Returning [%s + %s = %s]"%(req.a, req.b, (req.a + req.b)))
    return AddTwoIntsResponse(req.a + req.b)

def add_two_ints_server():
    rospy.init_node('add_two_ints_server')
    s = rospy.Service('add_two_ints', AddTwoInts, handle_add_two_ints)
    print("Ready to add two ints.")
    rospy.spin()

if __name__ == "__main__":
    add_two_ints_server()
"""

CLIENT = """\
#!/usr/bin/env python
from __future__ import print_function

import sys
import rospy
from beginner_tutorials.srv import *

def add_two_ints_client(x, y):
    rospy.wait_for_service('add_two_ints')
    try:
        add_two_ints = rospy.ServiceProxy('add_two_ints', AddTwoInts)
        resp1 = add_two_ints(x, y)
        return resp1.sum
    except rospy.ServiceException as e:
        print("Service call failed: %s"%e)

def usage():
    return "%s [x y]"%sys.argv[0]

if __name__ == "__main__":
    if len(sys.argv) == 3:
        x = int(sys.argv[1])
        y = int(sys.argv[2])
    else:
        print(usage())
        sys.exit(1)
    print("Requesting %s+%s"%(x, y))
    print("%s + %s = %s"%(x, y, add_two_ints_client(x, y)))
"""


class Terminal:
    """bash as the tutorials' user has it: rosx's shell integration, the workspace sourced once
    it is built, ``ROS_MASTER_URI`` on a free port (never 11311)."""

    def __init__(self, home: Path) -> None:
        self.home = home
        self.port = free_port()
        self.env = clean_environ(HOME=str(home), ROS_MASTER_URI=f"http://localhost:{self.port}")
        # The test run's own variables (CI's ROS 1 reference, ROS1_*) are no user's either;
        # without XDG_CACHE_HOME, shell-init writes its programs under this HOME.
        for name in (
            "CMAKE_PREFIX_PATH",
            "PYTHONPATH",
            "ROSLISP_PACKAGE_DIRECTORIES",
            "XDG_CACHE_HOME",
        ):
            self.env.pop(name, None)
        for name in [k for k in self.env if k.startswith("ROS1_")]:
            self.env.pop(name)
        self.background: list[subprocess.Popen[str]] = []

    def script(self, commands: str) -> str:
        return (
            f'eval "$({sys.executable} -m rosx_commands shell-init bash)"\n'
            "if [ -f ~/catkin_ws/devel/setup.bash ]; then source ~/catkin_ws/devel/setup.bash; fi\n"
            "cd ~\n" + textwrap.dedent(commands)
        )

    def run(self, commands: str, stdin: str = "", timeout: float = 120) -> str:
        """Run ``commands``; their stdout (stderr goes with it, as a terminal shows both)."""
        done = subprocess.run(
            ["bash", "-c", self.script(commands)],
            env=self.env,
            input=stdin,
            capture_output=True,
            text=True,
            timeout=timeout,
            check=False,
        )
        return done.stdout + done.stderr

    def start(self, commands: str, log: str) -> Path:
        """Run ``commands`` in the background (another terminal); their output goes to ``log``."""
        path = self.home / log
        with path.open("w") as out:
            self.background.append(
                subprocess.Popen(
                    ["bash", "-c", self.script(commands)],
                    env=self.env,
                    stdin=subprocess.DEVNULL,
                    stdout=out,
                    stderr=subprocess.STDOUT,
                    text=True,
                    start_new_session=True,
                )
            )
        return path

    def stop_last(self) -> None:
        stop(self.background.pop())

    def wait_last(self, timeout: float = 60) -> None:
        """Wait for the last program started in the background to end by itself."""
        self.background.pop().wait(timeout)

    def close(self) -> None:
        while self.background:
            self.stop_last()


@pytest.fixture
def terminal(tmp_path: Path) -> Iterator[Terminal]:
    if shutil.which("bash") is None:
        pytest.skip("bash is not installed")
    home = tmp_path / "home"
    home.mkdir()
    term = Terminal(home)
    try:
        yield term
    finally:
        term.close()


def debian_rospack(*argv: str, package_path: str) -> str:
    assert DEBIAN_ROSPACK is not None
    return subprocess.run(
        [DEBIAN_ROSPACK, *argv],
        env=clean_environ(ROS_PACKAGE_PATH=package_path),
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    ).stdout


def edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, (path, old)
    path.write_text(text.replace(old, new))


def test_the_beginner_tutorials(terminal: Terminal) -> None:  # noqa: PLR0915 - one walk, in order
    t = terminal
    home = t.home
    ws = home / "catkin_ws"
    pkg = ws / "src" / "beginner_tutorials"

    # 1. Installing and Configuring Your ROS Environment
    env_lines = t.run("printenv | grep ROS | sort").splitlines()
    assert env_lines == [
        "ROSLISP_PACKAGE_DIRECTORIES=",
        "ROS_DISTRO=noetic",
        f"ROS_ETC_DIR={ROS_ETC_DIR}",
        f"ROS_MASTER_URI=http://localhost:{t.port}",
        f"ROS_PACKAGE_PATH={SHARE}",
        "ROS_PYTHON_VERSION=3",
        f"ROS_ROOT={ROS_ROOT}",
        "ROS_VERSION=1",
    ]
    built = t.run("mkdir -p ~/catkin_ws/src\ncd ~/catkin_ws/\ncatkin_make")
    assert f"Base path: {ws}\n" in built and "-- Build files have been written to" in built
    path = t.run('source devel/setup.bash 2>/dev/null; echo "$ROS_PACKAGE_PATH"')
    assert path == f"{ws}/src:{SHARE}\n"

    # 2. Navigating the ROS Filesystem
    assert t.run("rospack find roscpp") == f"{SHARE}/roscpp\n"
    assert t.run("roscd roscpp\npwd") == f"{SHARE}/roscpp\n"
    assert t.run("roscd roscpp/msg\npwd") == f"{SHARE}/roscpp/msg\n"
    assert t.run("rosls roscpp_tutorials").split() == sorted(
        p.name for p in (SHARE / "roscpp_tutorials").iterdir()
    )
    completions = t.run("rosx complete 1 roscd roscpp_tut | tr '\\0' '\\n'")
    assert completions == "roscpp_tutorials/\n"  # what <TAB> after 'roscd roscpp_tut' adds
    assert "No active roscore" in t.run("roscd log")

    # 3. Creating a ROS Package
    created = t.run(
        "cd ~/catkin_ws/src\ncatkin_create_pkg beginner_tutorials std_msgs rospy roscpp"
    )
    assert created.endswith(
        f"Successfully created files in {pkg}. Please adjust the values in package.xml.\n"
    )
    t.run("cd ~/catkin_ws\ncatkin_make")
    assert t.run("rospack depends1 beginner_tutorials") == "roscpp\nrospy\nstd_msgs\n"
    assert t.run("roscd beginner_tutorials\npwd") == f"{pkg}\n"
    depends1_rospy = t.run("rospack depends1 rospy")
    assert depends1_rospy == "genpy\nroscpp\nrosgraph\nrosgraph_msgs\nroslib\nstd_msgs\n"
    depends = t.run("rospack depends beginner_tutorials")
    assert depends.splitlines()[:3] == ["cpp_common", "rostime", "roscpp_traits"]
    if DEBIAN_ROSPACK is not None:
        package_path = f"{ws}/src:{SHARE}"
        for argv in (["depends1", "rospy"], ["depends", "beginner_tutorials"]):
            ours = t.run(f"rospack {' '.join(argv)}")
            assert ours == debian_rospack(*argv, package_path=package_path), argv

    # 4. Building a ROS Package
    built = t.run("cd ~/catkin_ws\ncatkin_make\nls")
    assert built.endswith("build\ndevel\nsrc\n")
    installed = t.run("cd ~/catkin_ws\ncatkin_make install >/dev/null\nls install")
    # bin/: ROS 1's command names, which setup.bash puts on PATH as Noetic's does.
    assert installed.split() == ["bin", "setup.bash", "setup.sh", "setup.zsh", "share"]

    # 5. Understanding ROS Nodes
    t.start(f"roscore -p {t.port}", "roscore.log")
    wait_for(lambda: port_open(t.port), what="roscore")
    wait_for(lambda: t.run("rosnode list") == "/rosout\n", what="/rosout")
    info = t.run("rosnode info /rosout")
    assert info.startswith("-" * 80 + "\nNode [/rosout]\nPublications: \n * /rosout_agg")
    t.start("rosrun turtlesim turtlesim_node", "turtlesim.log")
    wait_for(lambda: "/turtlesim" in t.run("rosnode list").split(), what="/turtlesim")
    t.start("rosrun turtlesim turtlesim_node __name:=my_turtle", "my_turtle.log")
    wait_for(lambda: "/my_turtle" in t.run("rosnode list").split(), what="/my_turtle")
    ping = t.run("rosnode ping -c 2 my_turtle")
    assert ping.startswith(
        "rosnode: node is [/my_turtle]\npinging /my_turtle with a timeout of 3.0s"
    )
    assert len(re.findall(r"xmlrpc reply from http://\S+\ttime=", ping)) == 2
    # my_turtle took over turtlesim's services; as in the tutorial, one turtlesim goes on
    t.stop_last()
    t.stop_last()
    t.start("rosrun turtlesim turtlesim_node", "turtlesim.log")
    wait_for(lambda: "/clear" in t.run("rosservice list").split(), what="turtlesim's services")

    # 6. Understanding ROS Topics (the keyboard's part by rostopic pub; rqt_graph/rqt_plot aside)
    listing = t.run("rostopic list -v")
    assert " * /turtle1/cmd_vel [geometry_msgs/Twist] 1 subscriber" in listing
    assert t.run("rostopic type /turtle1/cmd_vel") == "geometry_msgs/Twist\n"
    shown = t.run("rostopic type /turtle1/cmd_vel | rosmsg show")
    assert shown == t.run("rosmsg show geometry_msgs/Twist")
    assert shown.startswith("geometry_msgs/Vector3 linear\n  float64 x\n")
    before = t.run("rostopic echo -n 1 /turtle1/pose")
    t.run(
        "rostopic pub -1 /turtle1/cmd_vel geometry_msgs/Twist -- '[2.0, 0.0, 0.0]' '[0.0, 0.0, 1.8]'"
    )
    wait_for(lambda: t.run("rostopic echo -n 1 /turtle1/pose") != before, what="the turtle moving")
    # timeout runs a program: rosx's, from the workspace's devel/bin (sourced after shell-init,
    # it comes first, as Noetic's does), not Debian's /usr/bin/rostopic where the ROS 1
    # reference is installed.
    found = Path(t.run("type -P rostopic").strip())
    assert found == t.home / "catkin_ws" / "devel" / "bin" / "rostopic"
    assert f'exec {sys.executable} -m rosx_commands rostopic "$@"' in found.read_text()

    # timeout's SIGINT after 3 s is the tutorial's Ctrl-C; on a loaded machine the first report
    # can miss it, and the user types the command again.
    def hz_reports_a_rate() -> bool:
        hz = t.run("timeout -s INT 3 rostopic hz /turtle1/pose")
        return "subscribed to [/turtle1/pose]" in hz and "average rate: " in hz

    wait_for(hz_reports_a_rate, timeout=60, what="rostopic hz reporting a rate")

    # 7. Understanding ROS Services and Parameters
    services = t.run("rosservice list").split()
    assert {"/clear", "/kill", "/reset", "/spawn", "/turtle1/set_pen"} <= set(services)
    assert t.run("rosservice type /clear") == "std_srvs/Empty\n"
    assert t.run("rosservice call /clear") == "\n"
    assert t.run("rosservice type /spawn | rossrv show") == (
        "float32 x\nfloat32 y\nfloat32 theta\nstring name\n---\nstring name\n\n"
    )
    assert t.run('rosservice call /spawn 2 2 0.2 ""') == 'name: "turtle2"\n'
    assert "/turtlesim/background_r" in t.run("rosparam list").split()
    t.run("rosparam set /turtlesim/background_r 150\nrosservice call /clear")
    assert t.run("rosparam get /turtlesim/background_r") == "150\n"
    assert t.run("rosparam get /turtlesim/background_g") == "86\n"
    t.run("rosparam dump params.yaml\nrosparam load params.yaml copy_turtle")
    assert t.run("rosparam get /copy_turtle/turtlesim/background_b") == "255\n"

    # 8. Using rqt_console and roslaunch (rqt_console is a terminal UI, tested in tests/tui)
    if "roslaunch" in TOOLS:
        (pkg / "launch").mkdir()
        (pkg / "launch" / "turtlemimic.launch").write_text(TURTLEMIMIC)
        t.start(
            "roscd beginner_tutorials\nroslaunch beginner_tutorials turtlemimic.launch", "l.log"
        )
        launched = {"/turtlesim1/sim", "/turtlesim2/sim", "/mimic"}
        wait_for(lambda: launched <= set(t.run("rosnode list").split()), what="the launch")
        start = t.run("rostopic echo -n 1 /turtlesim2/turtle1/pose")
        t.run(
            "rostopic pub -1 /turtlesim1/turtle1/cmd_vel geometry_msgs/Twist -- "
            "'[2.0, 0.0, 0.0]' '[0.0, 0.0, -1.8]'"
        )
        wait_for(
            lambda: t.run("rostopic echo -n 1 /turtlesim2/turtle1/pose") != start,
            what="turtlesim2 mimicking turtlesim1",
        )
        t.stop_last()

    # 9. Using rosed
    editor = home / "editor"
    editor.write_text(f'#!/bin/sh\necho "edited $1" > {home}/edited\n')
    editor.chmod(0o755)
    t.run(f"EDITOR={editor} rosed roscpp Logger.msg")
    assert (home / "edited").read_text() == f"edited {SHARE}/roscpp/msg/Logger.msg\n"

    # 10. Creating a ROS msg and srv
    t.run(
        """\
        roscd beginner_tutorials
        mkdir msg
        echo "int64 num" > msg/Num.msg
        """
    )
    (pkg / "msg" / "Num.msg").write_text(
        "string first_name\nstring last_name\nuint8 age\nuint32 score\n"
    )
    manifest = pkg / "package.xml"
    edit(
        manifest,
        "<!--   <build_depend>message_generation</build_depend> -->",
        "<build_depend>message_generation</build_depend>",
    )
    edit(
        manifest,
        "<!--   <exec_depend>message_runtime</exec_depend> -->",
        "<exec_depend>message_runtime</exec_depend>",
    )
    cmake = pkg / "CMakeLists.txt"
    edit(cmake, "  std_msgs\n)", "  std_msgs\n  message_generation\n)")
    edit(
        cmake,
        "# add_message_files(\n#   FILES\n#   Message1.msg\n#   Message2.msg\n# )",
        "add_message_files(\n  FILES\n  Num.msg\n)",
    )
    edit(
        cmake,
        "# generate_messages(\n#   DEPENDENCIES\n#   std_msgs\n# )",
        "generate_messages(\n  DEPENDENCIES\n  std_msgs\n)",
    )
    num = "string first_name\nstring last_name\nuint8 age\nuint32 score\n\n"
    assert t.run("rosmsg show beginner_tutorials/Num") == num
    assert t.run("rosmsg show Num") == f"[beginner_tutorials/Num]:\n{num}"
    t.run(
        "roscd beginner_tutorials\nmkdir srv\nroscp rospy_tutorials AddTwoInts.srv srv/AddTwoInts.srv"
    )
    edit(
        cmake,
        "# add_service_files(\n#   FILES\n#   Service1.srv\n#   Service2.srv\n# )",
        "add_service_files(\n  FILES\n  AddTwoInts.srv\n)",
    )
    add = "int64 a\nint64 b\n---\nint64 sum\n\n"
    assert t.run("rossrv show beginner_tutorials/AddTwoInts") == add
    assert t.run("rossrv show AddTwoInts") == (
        f"[beginner_tutorials/AddTwoInts]:\n{add}[rospy_tutorials/AddTwoInts]:\n{add}"
    )
    made = t.run("roscd beginner_tutorials\ncd ../..\ncatkin_make")
    assert "Generating Python from MSG beginner_tutorials/Num" in made
    assert "Generating Python code from SRV beginner_tutorials/AddTwoInts" in made

    # 12. Writing a Simple Publisher and Subscriber (Python)
    scripts = pkg / "scripts"
    scripts.mkdir()
    for name, text in (
        ("talker.py", TALKER),
        ("listener.py", LISTENER),
        ("add_two_ints_server.py", SERVER),
        ("add_two_ints_client.py", CLIENT),
    ):
        (scripts / name).write_text(text)
        (scripts / name).chmod(0o755)
    edit(
        cmake,
        "# catkin_install_python(PROGRAMS\n#   scripts/my_python_script\n#   DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}\n# )",
        "catkin_install_python(PROGRAMS scripts/talker.py scripts/listener.py\n"
        "  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}\n)",
    )
    assert "[100%]" in t.run("cd ~/catkin_ws\ncatkin_make")

    # 13. Examining the Simple Publisher and Subscriber
    talker = t.start("rosrun beginner_tutorials talker.py", "talker.log")
    listener = t.start("rosrun beginner_tutorials listener.py", "listener.log")
    wait_for(lambda: "I heard hello world" in listener.read_text(), what="the listener")
    assert re.match(r"\[INFO\] \[\d+\.\d+\]: hello world \d+\.\d+\n", talker.read_text())
    t.stop_last()
    t.stop_last()

    # 15/16. Writing and examining a Simple Service and Client (Python)
    server = t.start("rosrun beginner_tutorials add_two_ints_server.py", "server.log")
    wait_for(lambda: "Ready to add two ints." in server.read_text(), what="the server")
    assert t.run("rosrun beginner_tutorials add_two_ints_client.py 1 3") == (
        "Requesting 1+3\n1 + 3 = 4\n"
    )
    wait_for(lambda: "Returning [1 + 3 = 4]" in server.read_text(), what="the server's answer")
    t.stop_last()

    # 17. Recording and playing back data
    t.run("mkdir ~/bagfiles")
    t.start(
        "rostopic pub -r 10 /turtle1/cmd_vel geometry_msgs/Twist -- '[1.0, 0, 0]' '[0, 0, 1.0]'",
        "p",
    )
    recorded = t.run(
        "cd ~/bagfiles\nrosbag record -O subset --duration=2 /turtle1/cmd_vel /turtle1/pose"
    )
    t.stop_last()
    assert "Recording to 'subset.bag'." in recorded
    info = t.run("cd ~/bagfiles\nrosbag info subset.bag")
    assert re.search(r"topics:\s+/turtle1/cmd_vel\s+\d+ msgs\s+: geometry_msgs/Twist", info)
    assert "/turtle1/pose" in info

    # 18. Reading messages from a bag file (played while rostopic echo listens)
    echo = t.start("rostopic echo -n 2 /turtle1/cmd_vel", "echo.log")
    wait_for(lambda: "/rostopic" in t.run("rosnode list"), what="rostopic echo")
    t.run("cd ~/bagfiles\nrosbag play --immediate subset.bag --topics /turtle1/cmd_vel")
    wait_for(lambda: echo.read_text().count("linear:") == 2, what="the bag's messages echoed")
    # roswtf's online checks below see the graph as it is: rostopic echo -n 2 ends after its
    # two messages, and must have left it before (else ROS 1's roswtf and rosx's, one after the
    # other, would each see it at a different moment of its leaving).
    t.wait_last()
    wait_for(lambda: "/rostopic" not in t.run("rosnode list"), what="rostopic echo gone")

    # 19. Getting started with roswtf
    wtf = t.run("roscd beginner_tutorials\nroswtf")
    assert wtf.startswith(
        "Package: beginner_tutorials\n" + "=" * 80 + "\nStatic checks summary:\n\n"
        "No errors or warnings\n" + "=" * 80 + "\n"
        "Beginning tests of your ROS graph. These may take a while...\n"
    )
    assert "Online checks summary:" in wtf
    offline = t.run("roscd beginner_tutorials\nroswtf --offline")
    assert offline.endswith(
        "ROS Master does not appear to be running.\nOnline graph checks will not be run.\n"
        f"ROS_MASTER_URI is [http://localhost:{t.port}]\n"
    )
    if ROS1:
        # rosx has no rosdep: the database roswtf looks for exists for Debian's roswtf.
        (home / ".ros" / "rosdep" / "sources.cache").mkdir(parents=True)
        (home / ".ros" / "rosdep" / "sources.cache" / "index").touch()
        # Debian's roswtf runs the program `rospack export …`: Debian's, as in a ROS 1 shell
        # (shell-init's PATH would give it rosx's, which has no `export`).
        theirs = t.run(
            "roscd beginner_tutorials\n"
            "PATH=/usr/bin:$PATH PYTHONPATH= ROS_PACKAGE_PATH=$ROS_PACKAGE_PATH:/usr/share"
            " /usr/bin/roswtf 2>&1 | grep -v 'rosdep view is empty'"
        )
        ours = t.run(
            "roscd beginner_tutorials\nPYTHONPATH= ROS_PACKAGE_PATH=$ROS_PACKAGE_PATH:/usr/share"
            " roswtf"
        )
        assert ours == theirs
