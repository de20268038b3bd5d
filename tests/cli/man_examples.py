#!/usr/bin/env python3
"""Every example of the manual page (`sansui man`, EXAMPLES) runs as written, in order, from a
folder that holds the source tree's examples/: each must end with exit 0.

Usage: man_examples.py SANSUI SOURCE_DIR WORKDIR"""
import os
import re
import shutil
import subprocess
import sys

sansui, source, work = (os.path.abspath(a) for a in sys.argv[1:4])
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "out"))
os.symlink(os.path.join(source, "examples"), os.path.join(work, "examples"))
page = subprocess.run([sansui, "man"], capture_output=True, text=True, check=True).stdout
examples = page.split(".SH EXAMPLES\n", 1)[1].split(".SH ", 1)[0]
commands = [re.sub(r"\\(.)", r"\1", m) for m in re.findall(r"^\.TP\n\\fB(.*?)\\fR$", examples, re.M)]
assert len(commands) >= 5, commands
env = dict(os.environ, PATH=os.path.dirname(sansui) + os.pathsep + os.environ["PATH"])
failed = 0
for command in commands:
    done = subprocess.run(["bash", "-c", command], cwd=work, env=env, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    print(f"exit {done.returncode}: {command}")
    if done.returncode != 0:
        print(done.stderr)
        failed += 1
sys.exit(1 if failed else 0)
