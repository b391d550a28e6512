# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The vtkmlaa package after `cmake --install BUILD --prefix PREFIX`: a fresh /usr/bin/python3
with only PYTHONPATH=PREFIX/<site-packages> set (no LD_LIBRARY_PATH, no build tree on any path)
imports every class from the prefix, loads the project's libraries from PREFIX/lib (found through
the extension modules' $ORIGIN-relative RPATH), and runs the filter. Then
`DESTDIR=STAGE cmake --install BUILD --prefix /usr/local` puts the package where this interpreter
looks for packages under /usr/local without PYTHONPATH (site.getsitepackages(), and the same
directory for /usr when the interpreter's prefix is /usr).
Usage: TestPythonInstalledPackage.py BUILD_DIR WORK_DIR SITE_PACKAGES_SUFFIX [CMAKE]"""
import os
import shutil
import subprocess
import sys

build_dir, work_dir, suffix = sys.argv[1:4]
cmake = sys.argv[4] if len(sys.argv) > 4 else "cmake"
prefix = os.path.join(work_dir, "prefix")
shutil.rmtree(work_dir, ignore_errors=True)
os.makedirs(work_dir)
subprocess.run([cmake, "--install", build_dir, "--prefix", prefix], check=True,
               stdout=subprocess.DEVNULL)

package = os.path.join(prefix, suffix, "vtkmlaa")
for name in ("__init__.py", "vtkFiltersMLAA.so", "vtkRenderingMLAA.so"):
    if not os.path.isfile(os.path.join(package, name)):
        sys.exit("not installed: " + os.path.join(package, name))

child = r'''
import os, sys
prefix = os.path.realpath(sys.argv[1])
import vtkmlaa
from vtkmlaa import vtkImageMLAA, vtkOpenGLMLAAPass, vtkMLAAOptions, vtkImageDLAA
assert os.path.realpath(vtkmlaa.__file__).startswith(prefix + os.sep), vtkmlaa.__file__
for module in (vtkmlaa.vtkFiltersMLAA, vtkmlaa.vtkRenderingMLAA):
    assert os.path.realpath(module.__file__).startswith(prefix + os.sep), module.__file__
with open("/proc/self/maps") as maps:
    loaded = set(line.split()[-1] for line in maps if "MLAA" in line)
ours = [path for path in loaded if os.path.basename(path).startswith("libvtk")]
assert ours, "the project's libraries are not loaded: %s" % sorted(loaded)
for path in ours:
    assert os.path.realpath(path).startswith(prefix + os.sep), "loaded from outside: " + path
import numpy
image = numpy.zeros((8, 16), numpy.uint8)
image[4:, 6:] = 255  # a step down at x = 6 (an L: 135 next to it)
image[5:, :] = 255
out = vtkmlaa.antialias_array(image, preset="medium")
assert out[4, 6] == 135, out[4, 6]
print("installed package OK:", vtkmlaa.__file__, sorted(ours))
'''
environment = {"PATH": "/usr/bin:/bin", "PYTHONPATH": os.path.join(prefix, suffix),
               "HOME": work_dir, "PYTHONNOUSERSITE": "1"}
result = subprocess.run([sys.executable, "-c", child, prefix], env=environment, cwd=work_dir)
if result.returncode != 0:
    sys.exit(result.returncode)

# An install into /usr/local (staged with DESTDIR, as packagers do) lands on sys.path.
stage = os.path.join(work_dir, "stage")
subprocess.run([cmake, "--install", build_dir, "--prefix", "/usr/local"], check=True,
               stdout=subprocess.DEVNULL, env=dict(os.environ, DESTDIR=stage))
staged = os.path.join(stage, "usr/local", suffix, "vtkmlaa", "__init__.py")
if not os.path.isfile(staged):
    sys.exit("DESTDIR install: not installed: " + staged)
ask = "import site, sys; print(sys.prefix); print('\\n'.join(site.getsitepackages()))"
answer = subprocess.run([sys.executable, "-c", ask], check=True, capture_output=True, text=True,
                        env={"PATH": "/usr/bin:/bin", "HOME": work_dir}).stdout.split("\n")
python_prefix, searched = answer[0], [os.path.normpath(p) for p in answer[1:] if p]
for install_prefix in ["/usr/local"] + (["/usr"] if python_prefix == "/usr" else []):
    where = os.path.normpath(os.path.join(install_prefix, suffix))
    if where not in searched:
        sys.exit("%s does not look in %s for packages installed under %s (it looks in %s)"
                 % (sys.executable, where, install_prefix, searched))
print("installed with --prefix /usr/local into %s, where %s looks" % (
    os.path.join("/usr/local", suffix), sys.executable))
