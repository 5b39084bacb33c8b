#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that a machine has what the ROS page (docs/ros.md) and the rostests run, after
scripts/install_ros_deps.sh alone (CI runs it right after that script, the ctest
RosSegmentation.readmeCommandsFindTheirExecutables with the build's devel space):

1. every package of scripts/install_ros_deps.sh --list is installed (dpkg -s);
2. every command of docs/ros.md's code blocks, and of its inline code that starts
   with a ROS tool, finds its executable as it would run it: `rosrun PKG EXE` by rosrun's own
   lookup (rosrun --prefix echo), `roslaunch PKG FILE` its launch file and each node's
   executable in it, any other command on PATH (or the file it names);
3. every node and test of the rostests (ros/floodplane_ros/test/*.test) finds its executable;
4. the Python messages `rostopic echo` of the node's topics imports, for /usr/bin/python3.

Usage: check_ros_commands.py [DEVEL_SPACE]. Without the devel space (build/devel, made by a
build with the ROS node) the commands of floodplane_ros's own package are said to be skipped;
with it they are checked in its environment. Prints each missing thing on a line of its own and
exits 1 when there is one, 0 when every command finds what it runs.
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

ROOT = pathlib.Path(__file__).resolve().parent.parent
OWN_PACKAGE = "floodplane_ros"
# The messages of the node's topics and of the ones floodplane_ros/Planes contains.
ECHOED_MODULES = ["std_msgs.msg", "sensor_msgs.msg", "geometry_msgs.msg", "shape_msgs.msg",
                  "visualization_msgs.msg", "diagnostic_msgs.msg", "pcl_msgs.msg"]
SHELL_BUILTINS = ("cd", "source", ".", "export", "echo")
# Inline code in the page's text that is a command to check.
INLINE_TOOLS = ("rosrun ", "roslaunch ", "rostopic ", "rosservice ", "rosparam ", "rostest ", "rviz ",
                "roscore", "catkin_make", "/usr/bin/python3 /usr/lib/")


def ros_page(page):
    """The ROS page, docs/ros.md, whole."""
    return page.read_text(encoding="utf-8")


def code_commands(section):
    """The command lines of the section's shell code blocks (not its XML), continuation lines
    joined and comments dropped, then the inline code that starts with a ROS tool."""
    commands = []
    for language, block in re.findall(r"```(\w*)\n(.*?)```", section, flags=re.S):
        if language:
            continue
        joined = re.sub(r"\\\n\s*", " ", block)
        for line in joined.splitlines():
            words = shlex.split(line, comments=True)
            if words:
                commands.append(words)
    prose = re.sub(r"```.*?```", "", section, flags=re.S)
    for code in re.findall(r"`([^`]+)`", prose):
        if code.startswith(INLINE_TOOLS):
            commands.append(shlex.split(code.replace("\n", " ")))
    for package in re.findall(r"\$\(rospack find (\w+)\)", section):
        commands.append(["rospack", "find", package])
    return commands


def simple_commands(words):
    """The simple commands of one command line: split at && ; |, leading VAR=value dropped."""
    current = []
    for word in words + ["&&"]:
        if word in ("&&", ";", "|", "||"):
            while current and re.match(r"^[A-Za-z_][A-Za-z0-9_]*=", current[0]):
                current.pop(0)
            if current:
                yield current
            current = []
        else:
            current.append(word)


class Checker:
    def __init__(self, devel):
        self.devel = devel
        self.problems = []
        self.checked = 0
        self.skipped = set()
        self.home = tempfile.mkdtemp(prefix="check_ros_commands.")
        self.env = dict(os.environ, ROS_HOME=self.home)

    def run(self, command):
        """`command` in the ROS environment (the devel space's, when given)."""
        if self.devel:
            command = [str(self.devel / "env.sh")] + command
        return subprocess.run(command, env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)

    def problem(self, what, why):
        self.problems.append(f"{what}: {why}")

    def own(self, package, what):
        """Whether `package` is ours and there is no devel space to find it in."""
        if package == OWN_PACKAGE and not self.devel:
            self.skipped.add(what)
            return True
        return False

    def executable(self, package, name, what):
        """`name` of `package`, found as rosrun and roslaunch find a node's executable."""
        if self.own(package, what):
            return
        self.checked += 1
        found = self.run(["rosrun", "--prefix", "echo", package, name])
        if found.returncode != 0:
            self.problem(what, found.stdout.strip().splitlines()[-1] if found.stdout.strip() else "not found")

    def launch_nodes(self, launch_file, what):
        """Every node and test of a launch or rostest file finds its executable."""
        for element in ElementTree.parse(launch_file).iter():
            if element.tag in ("node", "test") and "pkg" in element.attrib:
                self.executable(element.attrib["pkg"], element.attrib["type"],
                                f"{what}: <{element.tag} pkg=\"{element.attrib['pkg']}\" type=\"{element.attrib['type']}\">")

    def command(self, words, what):
        tool = words[0]
        if tool == "rosrun":
            arguments = [word for word in words[1:] if not word.startswith("--")]
            self.executable(arguments[0], arguments[1], what)
        elif tool == "roslaunch":
            package, name = words[1], words[2]
            self.path_command(tool, what)
            if self.own(package, what):
                # Without the devel space, its nodes from the source, which the build installs.
                self.launch_nodes(ROOT / "ros" / package / "launch" / name, what)
                return
            self.checked += 1
            found = self.run(["roslaunch", "--files", package, name])
            if found.returncode != 0:
                self.problem(what, "no launch file " + name + " in " + package)
            else:
                self.launch_nodes(found.stdout.split()[0], what)
        elif tool == "rospack" and words[1:2] == ["find"]:
            if self.own(words[2], what):
                return
            self.checked += 1
            if self.run(words).returncode != 0:
                self.problem(what, "rospack does not find " + words[2])
        elif tool in SHELL_BUILTINS or tool.startswith("build/") or tool.startswith("~"):
            return  # the shell's own, or what the build makes
        elif tool.startswith("scripts/"):
            self.checked += 1
            if not os.access(ROOT / tool, os.X_OK):
                self.problem(what, f"{tool} is not an executable of the repository")
        elif tool.startswith("/"):
            self.checked += 1
            files = [word for word in words if word.startswith("/usr/")]
            missing = [file for file in files if not os.path.exists(file)]
            if missing:
                self.problem(what, "no " + ", ".join(missing))
        else:
            self.path_command(tool, what)

    def path_command(self, tool, what):
        self.checked += 1
        if shutil.which(tool, path=self.env.get("PATH")) is None:
            self.problem(what, f"{tool} is not on PATH")

    def packages(self):
        listed = subprocess.run([str(ROOT / "scripts/install_ros_deps.sh"), "--list"], stdout=subprocess.PIPE,
                                text=True, check=True).stdout.split()
        for package in listed:
            self.checked += 1
            status = subprocess.run(["dpkg", "-s", package], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                    text=True)
            if status.returncode != 0 or "Status: install ok installed" not in status.stdout:
                self.problem(f"package {package}", "not installed (scripts/install_ros_deps.sh installs it)")
        return len(listed)

    def echoed_messages(self):
        self.checked += 1
        imported = subprocess.run(["/usr/bin/python3", "-c", "import " + ", ".join(ECHOED_MODULES)],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if imported.returncode != 0:
            self.problem("rostopic echo's messages", imported.stdout.strip().splitlines()[-1])


def main():
    devel = pathlib.Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else None
    if devel and not (devel / "env.sh").exists():
        sys.exit(f"check_ros_commands: {devel} is not a catkin devel space (no env.sh)")
    checker = Checker(devel)
    try:
        packages = checker.packages()
        for words in code_commands(ros_page(ROOT / "docs" / "ros.md")):
            for simple in simple_commands(words):
                checker.command(simple, "docs/ros.md: " + " ".join(simple)[:100])
        for test in sorted((ROOT / "ros" / OWN_PACKAGE / "test").glob("*.test")):
            checker.launch_nodes(test, f"{test.relative_to(ROOT)}")
        checker.echoed_messages()
    finally:
        shutil.rmtree(checker.home, ignore_errors=True)
    for problem in checker.problems:
        print(f"check_ros_commands: missing: {problem}")
    if checker.skipped:
        print(f"check_ros_commands: {len(checker.skipped)} commands of {OWN_PACKAGE} skipped: no devel space given")
    if checker.problems:
        print(f"check_ros_commands: {len(checker.problems)} of {checker.checked} checks failed")
        return 1
    print(f"check_ros_commands: {packages} packages installed, {checker.checked} checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
