#!/usr/bin/env python3
"""Drives the real amls-editor in an X server (Xvfb) with real input (xdotool).

    python3 tests/editor_gui_test.py build/app/editor/amls-editor [build/app/amls] [--only=regions ...]

With the amls binary, the region test also replays the editor's saved scene with `amls deform`, and the open
cap's test moves its dense cap by the saved scene for the exact shape; --only= runs the named checks alone
(2d, open_without_normals, regions, region_edits, frames_during_heavy_step, open_cap_drag).

The test starts its own Xvfb (1280x800x24) on a display number Xvfb picks
itself (-displayfd: no race with other X servers on the machine, which
`xvfb-run -a` has); without Xvfb it uses $DISPLAY, e.g. under
`xvfb-run -a -s "-screen 0 1280x800x24" python3 tests/editor_gui_test.py ...`.

Checks, on a 2D scene (the unit circle): the editor starts with the handle of
the scene's first stage, Shift+click on the curve adds another,
a drag deforms the surface the way it says (Ctrl+S exports the result), the
interpolated variant (key I) changes the next export, F12 writes a screenshot
whose pixels show the surface and the handles; Esc and undo restore the
point set; on a 3D sphere opened from a scene with a pinned region, the
editor shows that region, an Alt+drag lasso makes another, a brush stroke (B)
a third that undo takes away; the lasso's region dragged by its marker and
turned with Ctrl+drag moves rigidly in the export while the pinned one stays,
and `amls deform` of the saved scene gives the export; the region window's
controls pressed with the mouse (add and subtract by lasso, invert, clear and
undo), P to pin, and Ctrl+Shift+drag to scale a region, whose export lies on
the sphere scaled with it; on a heavy 3D
scene, frames keep coming while the worker resamples; an open cap (tools/open_cap/) whose bottom pole
is dragged down in 30 steps stays open, its export on the exact shape.
The editor's debug log (--debug-log) says when it is ready and where the view
is. Exits 77 (skipped) without a display or xdotool.
"""
import json
import math
import os
import random
import re
import select
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

TIMEOUT = 30.0  # seconds to wait for any one thing


def fail(message):
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)
    print("ok: " + message, flush=True)


def wait_for(predicate, what, timeout=TIMEOUT):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.05)
    fail("timed out waiting for " + what)


def xdotool(*args):
    subprocess.run(["xdotool", *map(str, args)], check=True, capture_output=True)


class Editor:
    """One editor process, its debug log and its window."""

    def __init__(self, binary, folder, name, arguments, size="1000x700"):
        self.log_path = os.path.join(folder, name + ".log")
        self.process = subprocess.Popen([binary, "--debug-log", self.log_path, "--size", size, "--threads", "1",
                                         *arguments], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        self.window = wait_for(self.find_window, "the editor's window")
        xdotool("windowfocus", "--sync", self.window)
        self.releases = 0  # mouse buttons let go so far, each of which the editor logs

    def let_go(self, *action):
        """xdotool's mouseup or click: a button let go, which wait_idle() waits for the editor to read."""
        xdotool(*action)
        self.releases += 1

    def find_window(self):
        if self.process.poll() is not None:
            server = "" if XVFB is None else " (Xvfb %s)" % ("running" if XVFB.poll() is None else
                                                              "exited with %s" % XVFB.returncode)
            fail("the editor exited early%s:\n%s" % (server, self.process.stdout.read().decode(errors="replace")))
        found = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "^amls-editor"], capture_output=True,
                               text=True)
        ids = found.stdout.split()
        return ids[0] if ids else None

    def lines(self):
        try:
            with open(self.log_path) as f:
                return f.read().splitlines()
        except FileNotFoundError:
            return []

    def count(self, pattern):
        return sum(1 for line in self.lines() if re.search(pattern, line))

    def wait_line(self, pattern, after=0, what=None, timeout=TIMEOUT):
        """Waits for the (after+1)-th line matching `pattern`; returns it."""
        def find():
            matches = [line for line in self.lines() if re.search(pattern, line)]
            return matches[after] if len(matches) > after else None
        return wait_for(find, what or pattern, timeout)

    def wait_idle(self):
        """Waits until the editor has read every mouse button let go so far (a slow build, under a sanitizer,
        may still be working through a drag's motion when the test lets go) and the worker has applied
        everything: two idle frames after both the newest snapshot and the last release."""
        def idle():
            lines = self.lines()
            released = [i for i, l in enumerate(lines) if re.search(r" button \d+ action=0 ", l)]
            last_snapshot = max((i for i, l in enumerate(lines) if " snapshot " in l), default=-1)
            after = max(last_snapshot, released[-1] if released else -1)
            idle_frames = [l for l in lines[after + 1:] if re.search(r" frame \d+ busy=0", l)]
            return len(released) >= self.releases and len(idle_frames) >= 2
        wait_for(idle, "the worker to be idle")

    def view_fields(self):
        """The fields of the newest `view` line of the log."""
        line = [l for l in self.lines() if " view mode=" in l][-1]
        return dict(re.findall(r"(\w+)=(\S+)", line))

    def view(self):
        fields = self.view_fields()
        target = [float(v) for v in fields["target"].split(",")]
        width, height = (int(v) for v in fields["viewport"].split("x"))
        return {"target": target, "half_height": float(fields["half_height"]), "width": width, "height": height,
                "ppu": float(fields["pixels_per_unit"])}

    def to_window(self, x, y):
        """Window coordinates of a world point in the planar (2D) view."""
        v = self.view()
        aspect = v["width"] / v["height"]
        px = ((x - v["target"][0]) / (v["half_height"] * aspect) * 0.5 + 0.5) * v["width"]
        py = (0.5 - (y - v["target"][1]) / v["half_height"] * 0.5) * v["height"]
        return round(px / v["ppu"]), round(py / v["ppu"])

    def move(self, x, y):
        xdotool("mousemove", "--window", self.window, x, y)

    def key(self, keys):
        xdotool("key", keys)

    def quit(self):
        self.key("ctrl+q")
        try:
            self.process.wait(timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            self.process.kill()
            fail("the editor did not quit on Ctrl+Q")
        if self.process.returncode != 0:
            output = self.process.stdout.read().decode(errors="replace")
            fail("the editor quits cleanly on Ctrl+Q (exit status %d; its last output:\n%s)" %
                 (self.process.returncode, output[-4000:]))
        check(True, "the editor quits cleanly on Ctrl+Q")


def read_ply(path, coordinates=2):
    """(x, y), or (x, y, z), of every point of a binary little-endian PLY with double positions and normals, and
    possibly the rim mark (a uchar), as the editor writes."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    count = int(next(l.split()[2] for l in header if l.startswith("element vertex")))
    properties = [tuple(l.split()[1:3]) for l in header if l.startswith("property")]
    check("binary_little_endian" in header[1], "the export is binary PLY")
    check([name for _, name in properties[:6]] == ["x", "y", "z", "nx", "ny", "nz"] and
          all(kind == "double" for kind, _ in properties[:6]), "the export has positions and normals")
    check(properties[6:] in ([], [("uchar", "rim")]), "the export has nothing but the rim mark besides")
    stride = 8 * 6 + len(properties[6:])
    return [struct.unpack_from("<%dd" % coordinates, data, end + i * stride) for i in range(count)]


def read_png(path):
    """(width, height, rows of RGBA tuples) of an 8-bit RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and color == 6, "expected 8-bit RGBA"
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, previous = zlib.decompress(idat), 4 * width, [], bytearray(4 * width)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - 4] if i >= 4 else 0
            up, corner = previous[i], previous[i - 4] if i >= 4 else 0
            if kind == 1:
                line[i] = (line[i] + left) & 255
            elif kind == 2:
                line[i] = (line[i] + up) & 255
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
        rows.append([tuple(line[4 * x:4 * x + 4]) for x in range(width)])
        previous = line
    return width, height, rows


def near(color, reference, tolerance=40):
    return all(abs(int(a) - int(b)) <= tolerance for a, b in zip(color, reference))


def drag(editor, start, end, steps=12, button=1):
    editor.move(*start)
    time.sleep(0.2)
    xdotool("mousedown", button)
    for k in range(1, steps + 1):
        time.sleep(0.04)
        editor.move(round(start[0] + (end[0] - start[0]) * k / steps), round(start[1] + (end[1] - start[1]) * k / steps))
    time.sleep(0.2)
    editor.let_go("mouseup", button)


def shift_click(editor, at):
    editor.move(*at)
    time.sleep(0.2)
    xdotool("keydown", "shift")
    time.sleep(0.1)
    editor.let_go("click", 1)
    time.sleep(0.1)
    xdotool("keyup", "shift")


def export(editor, path, nth, coordinates=2):
    editor.wait_idle()
    editor.key("ctrl+s")
    editor.wait_line("message level=info Exported", after=nth, what="export number %d" % (nth + 1))
    return read_ply(path, coordinates)


def write_scene(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def test_2d(binary, folder):
    # The scene's first stage puts a handle at the bottom: the editor starts with it.
    scene = write_scene(folder, "circle.json",
                        '{"dimension": 2, "name": "circle", "shape": {"type": "circle", "radius": 1, "points": 250},'
                        ' "grid": {"spacing": 0.024}, "stages": [{"handles": [[0, -1]],'
                        ' "targets": [{"steps": 1, "handles": [[0, -1.2]]}]}]}')
    out, shot = os.path.join(folder, "out.ply"), os.path.join(folder, "shot.png")
    editor = Editor(binary, folder, "editor2d", [scene, "--export", out, "--screenshot", shot])
    editor.wait_line(r"snapshot .* load=1 dimension=2 points=250", what="the 2D scene to load")
    editor.wait_idle()

    # Two handles (the left half of the circle is under the side panel): the scene's at the bottom stays,
    # a Shift+click adds one at the right end, which is dragged half a unit to the right.
    editor.wait_line(r" frame \d+ .*handles=1 ", what="the scene's handle")
    shift_click(editor, editor.to_window(1.0, 0.0))
    editor.wait_line(r" frame \d+ .*handles=2 ", what="the added handle")
    start, end = editor.to_window(1.0, 0.0), editor.to_window(1.5, 0.0)
    drag(editor, start, end)
    points = export(editor, out, 0)
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    print("exported %d points, x in [%.4f, %.4f], y in [%.4f, %.4f]" % (len(points), min(xs), max(xs), min(ys), max(ys)))
    pixel = 2.0 * editor.view()["half_height"] / editor.view()["height"] * editor.view()["ppu"]
    check(abs(max(xs) - 1.5) < 0.02 + 2 * pixel, "the dragged end moved to x = 1.5 (%.4f)" % max(xs))
    check(abs(min(ys) + 1.0) < 0.02, "the held bottom stayed at y = -1 (%.4f)" % min(ys))
    check(0.7 < max(ys) < 1.3 and -1.3 < min(xs) < -0.7, "the rest of the curve stayed about in place")
    check(len(points) > 250, "the stretched curve was resampled at about h (%d points)" % len(points))

    # The interpolated variant resamples the surface at once: the next export differs, on the same shape.
    editor.key("i")
    editor.wait_line(r"snapshot .* variant=interpolated", what="the interpolated variant")
    interpolated = export(editor, out, 1)
    check(interpolated != points, "the interpolated variant's export differs from the exact one")
    check(abs(max(p[0] for p in interpolated) - max(xs)) < 0.02, "and holds the same shape")

    # A screenshot whose pixels show the surface, the selected handle and the background.
    editor.key("F12")
    editor.wait_line("message level=info Screenshot saved", what="the screenshot")
    width, height, rows = read_png(shot)
    view = editor.view()
    check((width, height) == (view["width"], view["height"]), "the screenshot has the framebuffer's size")
    hx, hy = (round(c * view["ppu"]) for c in editor.to_window(max(xs), 0.0))
    handle = rows[hy][hx]
    check(near(handle, (51, 230, 89), 60) or near(handle, (153, 255, 153), 60),
          "the selected handle is drawn at its place (%s)" % (handle,))
    background = rows[height // 2][(width + hx) // 2]
    check(near(background, (33, 36, 41), 12), "the view's background is clear beside the shape (%s)" % (background,))
    lit = sum(1 for row in rows[::2] for c in row[width // 3::2] if c[0] > 180 and c[1] > 150 and c[2] < 160)
    check(lit > 200, "the surface and the curve are drawn (%d sampled pixels)" % lit)

    # Esc during a drag restores the point set of mouse-down; Ctrl+Z undoes a finished drag.
    editor.wait_idle()
    before = export(editor, out, 2)
    editor.move(*editor.to_window(max(xs), 0.0))
    time.sleep(0.2)
    xdotool("mousedown", 1)
    for k in range(1, 8):
        time.sleep(0.04)
        editor.move(*editor.to_window(max(xs) + 0.05 * k, 0.1 * k))
    time.sleep(0.3)
    editor.key("Escape")
    time.sleep(0.1)
    editor.let_go("mouseup", 1)
    check(export(editor, out, 3) == before, "Esc restores the point set of mouse-down")
    drag(editor, editor.to_window(max(xs), 0.0), editor.to_window(max(xs), 0.4), steps=6)
    moved = export(editor, out, 4)
    check(moved != before, "a second drag changes the point set")
    editor.key("ctrl+z")
    editor.wait_line(r"snapshot .* steps=", after=0)
    check(export(editor, out, 5) == before, "Ctrl+Z restores the point set as it was at mouse-down")
    editor.quit()


def orbit_to_window(editor, p):
    """Window coordinates of a world point in the default orbit view (azimuth and elevation 0, 40 degree fov)."""
    line = [l for l in editor.lines() if " view mode=orbit" in l][-1]
    fields = dict(re.findall(r"(\w+)=(\S+)", line))
    if float(fields["azimuth"]) != 0 or float(fields["elevation"]) != 0:
        fail("the 3D view is not the default one: " + line)
    target = [float(v) for v in fields["target"].split(",")]
    distance, ppu = float(fields["distance"]), float(fields["pixels_per_unit"])
    width, height = (int(v) for v in fields["viewport"].split("x"))
    depth = target[2] + distance - p[2]
    tangent = 0.36397023426620234  # tan(20 degrees)
    nx = (p[0] - target[0]) / (depth * tangent * width / height)
    ny = (p[1] - target[1]) / (depth * tangent)
    return round((nx * 0.5 + 0.5) * width / ppu), round((0.5 - ny * 0.5) * height / ppu)


def lasso(editor, corners):
    """An Alt+drag along the corners and back to the first."""
    editor.move(*corners[0])
    time.sleep(0.2)
    xdotool("keydown", "alt")
    time.sleep(0.1)
    xdotool("mousedown", 1)
    for corner in corners[1:] + corners[:1]:
        time.sleep(0.04)
        editor.move(*corner)
    time.sleep(0.2)
    editor.let_go("mouseup", 1)
    time.sleep(0.1)
    xdotool("keyup", "alt")


def circle_on_sphere(editor, x, y, radius, corners=12):
    """The lasso corners of a circle of `radius` about (x, y) on the front of the unit sphere, on screen, from
    its bottom: the press must land on the view, and the side panel (about 360 pixels wide) may reach over the
    circle's left, Table 1's window over its right. The panel takes a press as soon as a frame has seen the
    cursor over it."""
    out = []
    for k in range(corners):
        a = math.pi * (1.5 + 2 * k / corners)
        px, py = x + radius * math.cos(a), y + radius * math.sin(a)
        out.append(orbit_to_window(editor, (px, py, math.sqrt(max(0.0, 1 - px * px - py * py)))))
    return out


def regions_line(editor, pattern):
    return editor.wait_line(r"regions " + pattern, what="regions " + pattern)


def regions_fields(editor):
    """The fields before the first region in the newest `regions` line of the log (count, active, drag, ring)."""
    line = [l for l in editor.lines() if "regions count=" in l][-1]
    return dict(re.findall(r"(\w+)=(\S+)", line.split(" | ")[0]))


def arc_drag(editor, centre, radius, angles, modifier=None):
    """A left drag along an arc of `radius` about `centre` (window units) through the angles (radians,
    counterclockwise on screen), with a modifier key held if one is given."""
    arc = [(round(centre[0] + radius * math.cos(a)), round(centre[1] - radius * math.sin(a))) for a in angles]
    editor.move(*arc[0])
    time.sleep(0.2)
    if modifier:
        xdotool("keydown", modifier)
        time.sleep(0.1)
    xdotool("mousedown", 1)
    for p in arc[1:]:
        time.sleep(0.04)
        editor.move(*p)
    time.sleep(0.2)
    editor.let_go("mouseup", 1)
    if modifier:
        time.sleep(0.1)
        xdotool("keyup", modifier)


def last_regions(editor):
    """The fields of each region in the newest `regions` line of the log."""
    line = [l for l in editor.lines() if "regions count=" in l][-1]
    out = []
    for part in line.split(" | ")[1:]:
        fields = dict(re.findall(r"(\w+)=(\S+)", part))
        out.append({key: [float(v) for v in fields[key].split(",")] for key in
                    ("marker", "translation", "rotation", "pivot")} | {"members": int(fields["members"]),
                                                                     "pinned": fields["pinned"] == "1"})
    return out


def rotated(vector, rotation):
    """The vector turned by a rotation vector (Rodrigues)."""
    angle = math.sqrt(sum(c * c for c in rotation))
    if angle == 0:
        return list(vector)
    k = [c / angle for c in rotation]
    cross = [k[1] * vector[2] - k[2] * vector[1], k[2] * vector[0] - k[0] * vector[2], k[0] * vector[1] - k[1] * vector[0]]
    dot = sum(a * b for a, b in zip(k, vector))
    c, s = math.cos(angle), math.sin(angle)
    return [vector[i] * c + cross[i] * s + k[i] * dot * (1 - c) for i in range(3)]


def at_rest(p, region):
    """Where a point the region's motion moved was before it: c + R^T (p - c - t)."""
    c, t, r = region["pivot"], region["translation"], region["rotation"]
    back = rotated([p[i] - c[i] - t[i] for i in range(3)], [-v for v in r])
    return [c[i] + back[i] for i in range(3)]


def pinned_cap_points():
    """Members of a region about (0, -0.75) on the front of the unit sphere, 0.03 apart (finer than h)."""
    out = []
    for i in range(-6, 7):
        for j in range(-6, 7):
            x, y = 0.03 * i, -0.75 + 0.03 * j
            if math.hypot(x, y + 0.75) <= 0.18:
                out.append("[%.6f, %.6f, %.6f]" % (x, y, math.sqrt(1 - x * x - y * y)))
    return ", ".join(out)


def test_regions(binary, folder, amls):
    # A handle at the back pole, which the drags leave in place, and a pinned region from the scene below the
    # front pole: the editor opens the scene with both.
    scene = write_scene(folder, "sphere_regions.json",
                        '{"dimension": 3, "name": "sphere", "shape": {"type": "sphere", "radius": 1, "points": 3000},'
                        ' "grid": {"spacing": 0.08}, "regions": [{"points": [%s]}],'
                        ' "stages": [{"handles": [[0, 0, -1]], "regions": [{"region": 0, "pinned": true}],'
                        ' "targets": [{"steps": 1, "handles": [[0, 0, -1]], "regions": [{}]}]}]}' % pinned_cap_points())
    out, saved = os.path.join(folder, "regions.ply"), os.path.join(folder, "regions-session.json")
    editor = Editor(binary, folder, "regions", [scene, "--export", out, "--scene-out", saved])
    editor.wait_line(r"snapshot .* load=1 dimension=3", what="the sphere to load")
    editor.wait_idle()
    h = 0.08
    regions_line(editor, r"count=1 active=-1 .*\| members=\d+ pinned=1 ")
    check(True, "the editor opened the scene's pinned region")

    # A lasso about the front pole: a moving region.
    lasso(editor, circle_on_sphere(editor, 0.0, 0.0, 0.45))
    regions_line(editor, r"count=2 active=1 .*\| members=\d+ pinned=0 ")
    editor.wait_idle()

    # The brush (B) paints a third region above the lasso's; undo takes it away again.
    editor.key("b")
    stroke = [orbit_to_window(editor, (x, y, math.sqrt(1 - x * x - y * y))) for x, y in ((-0.25, 0.6), (-0.05, 0.7))]
    drag(editor, stroke[0], stroke[1], steps=6)
    line = regions_line(editor, r"count=3 active=2 ")
    brushed = last_regions(editor)[2]["members"]
    check(brushed > 10, "a brush stroke made a region (%d members)" % brushed)
    editor.key("b")
    editor.wait_idle()
    editor.key("ctrl+z")
    regions_line(editor, r"count=2 active=-1 ")
    check(True, "undo took the brushed region away")
    members = [r["members"] for r in last_regions(editor)]
    check(members[0] > 10 and members[1] > 50, "the scene's region and the lasso's (%s members)" % members)

    # Drag the lasso's region by its marker to the right, then turn it with Ctrl about the view axis.
    marker = last_regions(editor)[1]["marker"]
    start = (round(marker[0]), round(marker[1]))
    drag(editor, start, (start[0] + 80, start[1]))
    editor.wait_idle()
    moved = last_regions(editor)[1]
    check(moved["translation"][0] > 0.1 and abs(moved["translation"][1]) < 0.02,
          "the marker's drag moved the region (%s)" % moved["translation"])
    marker = moved["marker"]
    # Turned by a sixteenth of a turn twice: the region's points moved as far in all as by one eighth, which
    # the cap follows within 0.05 h (every step's resample moves its points by a few thousandths of h).
    sixteenth = [k * math.pi / 8 / 6 for k in range(7)]
    # 9: within the marker's pick radius, so that the press grabs it.
    arc_drag(editor, marker, 9, sixteenth, modifier="ctrl")
    editor.wait_idle()
    turn = last_regions(editor)[1]["rotation"]
    check(0.25 < turn[2] < 0.55 and abs(turn[0]) < 1e-6 and abs(turn[1]) < 1e-6,
          "Ctrl+drag about the marker turned the region about the view axis (%s rad)" % turn)

    # The active region's ring (its radius in the log): a drag along it, no key held, turns the region on about
    # the axis toward the viewer by the angle swept.
    ring = float(regions_fields(editor)["ring"])
    check(ring > 20, "the active moving region shows its turning ring (radius %.1f)" % ring)
    before = editor.count(r"regions .* drag=ring ")
    arc_drag(editor, last_regions(editor)[1]["marker"], ring, [a - math.pi / 16 for a in sixteenth])
    editor.wait_idle()
    check(editor.count(r"regions .* drag=ring ") > before, "the debug log says the ring turned the region")
    region = last_regions(editor)[1]
    more = region["rotation"][2] - turn[2]
    check(0.25 < more < 0.55 and abs(region["rotation"][0]) < 1e-6 and abs(region["rotation"][1]) < 1e-6,
          "the ring's drag turned the region by %.3f rad more about the view axis" % more)
    points = export(editor, out, 0, 3)

    # No gap wider than 2 h among a sample of the points (each one's nearest neighbour within 2 h); that
    # the surface has no hole is checked against its exact shape after the replay below.
    spread = max(min(math.dist(p, q) for q in points if q is not p) for p in points[::25])
    check(spread < 2 * h, "no gap wider than 2 h among the sampled points (farthest nearest neighbour %.2f h)" % (spread / h))

    # Save Scene, then `amls deform` of the saved scene: its last frame is the export.
    editor.key("ctrl+shift+s")
    editor.wait_line("message level=info Saved the scene", what="the saved scene")

    # The moved cap lies on the sphere moved with it, the pinned one on the sphere itself, within 0.05 h: every
    # exported point within a region's reach of its members (as the saved scene has them), up to its rim.
    with open(saved) as f:
        saved_regions = json.load(f)["regions"]

    def within(rest, saved_region):
        reach = saved_region.get("reach", h)
        return any(math.dist(rest, m) <= reach for m in saved_region["points"])

    on_moved = [p for p in points if within(at_rest(p, region), saved_regions[1])]
    on_pinned = [p for p in points if within(p[:3], saved_regions[0])]
    off_moved = max(abs(math.hypot(*at_rest(p, region)) - 1.0) for p in on_moved)
    off_pinned = max(abs(math.hypot(*p[:3]) - 1.0) for p in on_pinned)
    check(len(on_moved) > 50 and off_moved < 0.05 * h,
          "the points of the dragged region moved with it, to its rim (%d, %.5f h off)" % (len(on_moved), off_moved / h))
    check(len(on_pinned) > 10 and off_pinned < 0.05 * h,
          "the points of the pinned region stayed (%d, %.5f h off)" % (len(on_pinned), off_pinned / h))

    # In brush mode a left drag that starts off the surface orbits, as on empty space outside it, and makes
    # no region; a middle drag orbits anywhere.
    editor.key("b")
    count = len(last_regions(editor))
    azimuth = float(editor.view_fields()["azimuth"])
    beside = orbit_to_window(editor, (1.3, 0.0, 0.0))
    drag(editor, beside, (beside[0] - 60, beside[1]))
    editor.wait_idle()
    orbited = float(editor.view_fields()["azimuth"])
    check(abs(orbited - azimuth) > 5 and len(last_regions(editor)) == count,
          "in brush mode a left drag off the surface orbits (azimuth %.1f to %.1f) and paints nothing" %
          (azimuth, orbited))
    middle = editor.view_fields()
    drag(editor, (500, 350), (500, 300), button=2)
    editor.wait_idle()
    check(float(editor.view_fields()["elevation"]) != float(middle["elevation"]) and
          editor.view_fields()["target"] == middle["target"] and len(last_regions(editor)) == count,
          "in brush mode a middle drag orbits (elevation %s to %s), not pans" %
          (middle["elevation"], editor.view_fields()["elevation"]))
    editor.quit()
    if amls:
        replay = os.path.join(folder, "replay")
        subprocess.run([amls, "deform", saved, "--out-dir", replay, "--tracers", "1", "--threads", "1"], check=True,
                       capture_output=True)
        frames = sorted(f for f in os.listdir(replay) if f.startswith("frame_"))
        replayed = read_ply(os.path.join(replay, frames[-1]), 3)
        worst = max((math.dist(a, b) for a, b in zip(points, replayed)), default=math.inf)
        check(len(replayed) == len(points) and worst < 1e-9,
              "amls deform of the saved scene gives the export (%d points, %.2g apart)" % (len(replayed), worst))
        # Closed between the regions: the replay's exact shape (the rest sphere carried by the same maps) has
        # every probe near one of the exported points, and F of those points is defined at every probe.
        with open(os.path.join(replay, "report.json")) as f:
            report = json.load(f)
        near = report["exact_to_points_h"]["max"]
        check(report["final_probe_holes"] == 0 and near < 1.5,
              "no hole between the regions: every probe of the exact shape within %.2f h of an exported point, "
              "F defined at all %d" % (near, report["probes"]))


def region_window(editor):
    """The centres of the region window's controls (window units), by label, from the newest line of the log."""
    line = [l for l in editor.lines() if " region-window " in l][-1]
    return {name: (round(float(x)), round(float(y))) for name, x, y in re.findall(r"(\w+)=(\S+),(\S+)", line)}


def press_control(editor, name):
    """A click on the region window's control `name`, as a user would press it."""
    editor.wait_idle()
    at = region_window(editor)[name]
    editor.move(*at)
    time.sleep(0.2)
    editor.let_go("click", 1)
    editor.wait_idle()


def regions_after(editor, pattern, action):
    """Does `action`, then waits for a new `regions` line matching `pattern` (not one logged before it)."""
    before = editor.count(r"regions " + pattern)
    action()
    return editor.wait_line(r"regions " + pattern, after=before, what="regions " + pattern)


def test_region_edits(binary, folder):
    # The selection edits and the region's own controls, pressed as a user would: add and subtract by lasso,
    # invert, pin with P, scale with Ctrl+Shift+drag, clear, undo.
    scene = write_scene(folder, "sphere_edits.json",
                        '{"dimension": 3, "name": "sphere", "shape": {"type": "sphere", "radius": 1, "points": 3000},'
                        ' "grid": {"spacing": 0.08}, "stages": [{"handles": [[0, 0, -1]],'
                        ' "targets": [{"steps": 1, "handles": [[0, 0, -1]]}]}]}')
    out = os.path.join(folder, "edits.ply")
    editor = Editor(binary, folder, "region_edits", [scene, "--export", out])
    editor.wait_line(r"snapshot .* load=1 dimension=3", what="the sphere to load")
    editor.wait_idle()
    h = 0.08
    lasso(editor, circle_on_sphere(editor, 0.0, 0.0, 0.3))
    regions_line(editor, r"count=1 active=0 ")
    first = last_regions(editor)[0]["members"]

    press_control(editor, "add")
    lasso(editor, circle_on_sphere(editor, 0.3, 0.0, 0.2))
    editor.wait_idle()
    added = last_regions(editor)
    check(len(added) == 1 and added[0]["members"] > first,
          "add: a second lasso grew the region (%d to %d members)" % (first, added[0]["members"]))

    press_control(editor, "subtract")
    lasso(editor, circle_on_sphere(editor, 0.0, 0.0, 0.15))
    editor.wait_idle()
    subtracted = last_regions(editor)
    check(len(subtracted) == 1 and subtracted[0]["members"] < added[0]["members"],
          "subtract: a lasso inside it took members away (%d to %d)" % (added[0]["members"], subtracted[0]["members"]))
    press_control(editor, "new")

    kept = subtracted[0]["members"]
    press_control(editor, "invert")
    inverted = last_regions(editor)[0]["members"]
    press_control(editor, "invert")
    back = last_regions(editor)[0]["members"]
    print("members: lasso %d, added %d, subtracted %d, inverted %d, inverted again %d" %
          (first, added[0]["members"], kept, inverted, back))
    check(inverted > 5 * kept and abs(back - kept) <= 0.1 * kept,
          "invert takes the rest of the surface (%d members), and again about the region before (%d of %d)" %
          (inverted, back, kept))

    regions_after(editor, r"count=1 .*\| members=\d+ pinned=1 ", lambda: editor.key("p"))
    regions_after(editor, r"count=1 .*\| members=\d+ pinned=0 ", lambda: editor.key("p"))
    check(True, "P pins the active region and P again lets it go")

    regions_after(editor, r"count=0 ", lambda: press_control(editor, "clear"))
    regions_after(editor, r"count=1 ", lambda: editor.key("ctrl+z"))
    check(True, "clear removes the active region, and undo brings it back")

    # A click on its marker makes it the active region again, and clear takes it away.
    editor.wait_idle()
    marker = last_regions(editor)[0]["marker"]
    editor.move(round(marker[0]), round(marker[1]))
    time.sleep(0.2)
    regions_after(editor, r"count=1 active=0 ", lambda: editor.let_go("click", 1))
    regions_after(editor, r"count=0 ", lambda: press_control(editor, "clear"))

    # A new region in its place; Ctrl+Shift+drag away from its marker scales it about its centre.
    regions_after(editor, r"count=1 active=0 ", lambda: lasso(editor, circle_on_sphere(editor, 0.0, 0.0, 0.45)))
    marker = last_regions(editor)[0]["marker"]
    start = (round(marker[0]) + 9, round(marker[1]))
    editor.move(*start)
    time.sleep(0.2)
    xdotool("keydown", "ctrl+shift")
    time.sleep(0.1)
    xdotool("mousedown", 1)
    for k in range(1, 3):
        time.sleep(0.04)
        editor.move(start[0] + k, start[1])
    time.sleep(0.2)
    editor.let_go("mouseup", 1)
    time.sleep(0.1)
    xdotool("keyup", "ctrl+shift")
    editor.wait_idle()
    region = last_regions(editor)[0]
    scale = float(dict(re.findall(r"(\w+)=(\S+)", [l for l in editor.lines() if "regions count=" in l][-1]
                                  .split(" | ")[1]))["scale"])
    check(1.1 < scale < 1.4, "Ctrl+Shift+drag scaled the region (by %.3f)" % scale)
    points = export(editor, out, 0, 3)
    # Inside the scaled region, well within its rim (its points resampled: it holds none), the surface is the
    # sphere scaled about the region's centre.
    c, t = region["pivot"], region["translation"]
    def scaled_back(p):
        return [c[i] + (p[i] - c[i] - t[i]) / scale for i in range(3)]
    inside = [p for p in points if math.hypot(*scaled_back(p)[:2]) < 0.15 and scaled_back(p)[2] > 0.5]
    off = max(abs(math.hypot(*scaled_back(p)) - 1.0) * scale for p in inside)
    check(len(inside) > 3 and off < 0.05 * h,
          "the scaled region's points lie on the sphere scaled with it (%d, %.4f h off)" % (len(inside), off / h))
    editor.quit()


def test_frames_during_heavy_step(binary, folder):
    scene = os.path.join(folder, "sphere.json")
    with open(scene, "w") as f:
        f.write('{"dimension": 3, "name": "sphere", "shape": {"type": "sphere", "radius": 1, "points": 100000},'
                ' "grid": {"spacing": 0.007}, "stages": [{"handles": [[0, 0, 1]],'
                ' "targets": [{"steps": 1, "handles": [[0, 0, 1.1]]}]}]}')
    # A small window: llvmpipe draws the 100 000 splats in software, on the cores the worker uses too.
    editor = Editor(binary, folder, "editor3d", [scene], size="640x480")
    editor.wait_line(r"snapshot .* load=1 dimension=3", what="the 3D scene to load")
    editor.wait_idle()
    editor.key("i")  # resamples the whole sphere on the worker
    editor.wait_line(r"snapshot .* variant=interpolated", what="the 3D resample to finish", timeout=120)
    times = []
    for line in editor.lines():
        m = re.match(r"t=(\S+) frame \d+ busy=1", line)
        if m:
            times.append(float(m.group(1)))
    busy = times[-1] - times[0] if times else 0.0
    gaps = [b - a for a, b in zip(times, times[1:])]
    print("busy for %.2f s over %d frames, longest gap %.3f s" % (busy, len(times), max(gaps, default=0.0)))
    # A UI that waited for the worker would show one gap as long as the whole step. Frames are slow here
    # (software GL on cores shared with the worker and other jobs, several times slower under the
    # sanitizers, and a frame can stall for a third of the step when other builds share the two cores), so
    # the bound is relative to the step: at least five frames, and no gap may hold half of it.
    check(busy > 0.6, "the 3D resample kept the worker busy for a while (%.2f s)" % busy)
    check(len(times) >= 5 and max(gaps) < busy / 2, "frames kept coming while the worker was busy")
    editor.quit()


def fibonacci_sphere(count):
    """A Fibonacci sphere of radius 1: count points with their outward normals."""
    for i in range(count):
        z = 1 - 2 * (i + 0.5) / count
        r, angle = math.sqrt(1 - z * z), i * math.pi * (3 - math.sqrt(5))
        yield r * math.cos(angle), r * math.sin(angle), z


def export_outward(editor, out):
    """Ctrl+S, then how many of the exported points' normals point outward, and how many were written."""
    editor.wait_idle()
    editor.key("ctrl+s")
    editor.wait_line("message level=info Exported", what="the export")
    with open(out, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    check("comment amls spacing " in header, "the export records its h")
    written = int(re.search(r"element vertex (\d+)", header).group(1))
    records = [struct.unpack_from("<6d", data, end + i * 48) for i in range(written)]
    return sum(1 for x, y, z, nx, ny, nz in records if x * nx + y * ny + z * nz > 0.9), written


def test_open_without_normals(binary, folder):
    """A scan without normals opens as `amls resample` opens it: normals estimated and outward; and
    one whose normals all point inward has them set aside and estimated under --normals estimated."""
    scan, out = os.path.join(folder, "scan.xyz"), os.path.join(folder, "scan-out.ply")
    count = 1500
    with open(scan, "w") as f:
        for x, y, z in fibonacci_sphere(count):  # positions only
            f.write("%.17g %.17g %.17g\n" % (x, y, z))
    editor = Editor(binary, folder, "editor-scan", [scan, "--export", out], size="640x480")
    editor.wait_line(r"snapshot .* load=1 dimension=3 points=%d" % count, what="the scan without normals to load")
    check(editor.count(r"message level=info .*normals estimated") == 1, "the editor says it estimated the normals")
    check(editor.count(r"message level=error") == 0, "opening the scan gave no error")
    outward, written = export_outward(editor, out)
    check(written > 0 and outward == written, "every estimated normal points outward (%d of %d)" % (outward, written))
    editor.quit()

    inward, out = os.path.join(folder, "inward.xyz"), os.path.join(folder, "inward-out.ply")
    with open(inward, "w") as f:
        for x, y, z in fibonacci_sphere(count):
            f.write("%.17g %.17g %.17g %.17g %.17g %.17g\n" % (x, y, z, -x, -y, -z))
    editor = Editor(binary, folder, "editor-inward", [inward, "--normals", "estimated", "--export", out],
                    size="640x480")
    editor.wait_line(r"snapshot .* load=1 dimension=3 points=%d" % count, what="the inward scan to load")
    check(editor.count(r"message level=info .*with normals, set aside; normals estimated") == 1,
          "the editor says it set the file's normals aside")
    outward, written = export_outward(editor, out)
    check(written > 0 and outward == written,
          "every normal points outward though the file's point inward (%d of %d)" % (outward, written))
    editor.quit()


def cap_scene(folder):
    """The open cap of tools/open_cap/ opening towards +y (the default view looks along -z), and a scene that
    holds it by four handles on its equator and puts one on its bottom pole."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "open_cap"))
    import make_cap
    with open(os.path.join(folder, "cap.xyz"), "w") as f:
        for p in make_cap.cap_points("y"):
            f.write("%.10f %.10f %.10f %.10f %.10f %.10f\n" % p)
    r = make_cap.RADIUS
    handles = "[0, %g, 0], [%g, 0, 0], [%g, 0, 0], [0, 0, %g], [0, 0, %g]" % (-r, r, -r, r, -r)
    return write_scene(folder, "cap.json",
                       '{"dimension": 3, "name": "cap", "shape": {"type": "file", "path": "cap.xyz"},'
                       ' "grid": {"spacing": 0.0436}, "widen_support": true,'
                       ' "stages": [{"handles": [%s], "targets": [{"steps": 1, "handles": [%s]}]}]}'
                       % (handles, handles)), make_cap


def test_open_cap_drag(binary, folder, amls):
    """A 30-step drag of an open cap's bottom pole a quarter of its size down keeps the cap open, and its
    export within 0.25 h mean of the exact shape (the dense cap moved by the same deformation)."""
    h = 0.0436
    scene, make_cap = cap_scene(folder)
    out, saved = os.path.join(folder, "cap.ply"), os.path.join(folder, "cap-session.json")
    editor = Editor(binary, folder, "cap", [scene, "--export", out, "--scene-out", saved])
    editor.wait_line(r"snapshot .* load=1 dimension=3", what="the cap to load")
    editor.wait_idle()
    bottom = -make_cap.RADIUS
    start = orbit_to_window(editor, (0.0, bottom, 0.0))
    end = orbit_to_window(editor, (0.0, bottom - 0.25, 0.0))
    steps = 30
    editor.move(*start)
    time.sleep(0.2)
    xdotool("mousedown", 1)
    for k in range(1, steps + 1):
        editor.move(start[0], round(start[1] + (end[1] - start[1]) * k / steps))
        # One step per move: the next move waits for this one's surface.
        editor.wait_line(r" snapshot .* steps=%d " % k, what="step %d's surface" % k)
    time.sleep(0.2)
    editor.let_go("mouseup", 1)
    points = export(editor, out, 0, 3)
    editor.key("ctrl+shift+s")
    editor.wait_line(r"message level=info Saved the scene .*\(%d steps\)" % steps, what="the saved scene")
    editor.quit()

    # Open: the rim stays where the cap was cut (the equator's handles hold it); a cap closing into an egg
    # puts points across its opening.
    rim_radius = math.sqrt(make_cap.RADIUS ** 2 - make_cap.CUT ** 2)
    top = max(p[1] for p in points)
    across = [p for p in points if p[1] > make_cap.CUT - h and math.hypot(p[0], p[2]) < 0.5 * rim_radius]
    check(top < make_cap.CUT + 0.5 * h and not across,
          "the dragged cap stays open (%d points, top %.3f h above the cut, %d across the opening)" %
          (len(points), (top - make_cap.CUT) / h, len(across)))
    if not amls:
        return
    # The exact shape: `amls deform` of the saved scene moves every point of the dense cap (about 0.3 h apart)
    # by the session's deformation (exact.ply, with normals); each exported point's distance to it is the
    # distance to the tangent plane of its nearest exact point.
    replay = os.path.join(folder, "cap-replay")
    subprocess.run([amls, "deform", saved, "--out-dir", replay, "--tracers", "1", "--frames-every", str(steps),
                    "--threads", "1"], check=True, capture_output=True)
    exact = read_ply(os.path.join(replay, "exact.ply"), 6)
    cells = {}
    for q in exact:
        cells.setdefault(tuple(math.floor(c / h) for c in q[:3]), []).append(q)

    def nearest(p):
        key = tuple(math.floor(c / h) for c in p[:3])
        around = [q for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                  for q in cells.get((key[0] + dx, key[1] + dy, key[2] + dz), ())]
        return min(around, key=lambda q: math.dist(p, q[:3]), default=None)

    distances = []
    for p in points:
        q = nearest(p)
        distances.append(abs(sum((p[i] - q[i]) * q[3 + i] for i in range(3))) / h if q else math.inf)
    mean = sum(distances) / len(distances)
    check(mean < 0.25, "the export lies on the exact shape: %.3f h mean, %.3f h max" % (mean, max(distances)))


XVFB = None  # the X server the test started, if any


def start_xvfb(log_path):
    """Starts Xvfb on a free display; sets DISPLAY; returns the process.

    The display number is random and high, and the server is checked to be ours by its screen size: X
    servers of other jobs on the machine may share the abstract socket namespace, where `:0` or the
    number `xvfb-run -a` picks may already be someone else's."""
    rng = random.Random()
    for _ in range(8):
        number = rng.randint(200, 30000)
        read_end, write_end = os.pipe()
        with open(log_path, "a") as log:
            # -noreset: an X server resets when its last client leaves (here the
            # probe below), and refuses connections while it does; the editor
            # starting right then failed with "Failed to open display".
            server = subprocess.Popen(["Xvfb", ":%d" % number, "-displayfd", str(write_end), "-screen", "0",
                                       "1280x800x24", "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,),
                                      stdout=log, stderr=subprocess.STDOUT)
        os.close(write_end)
        answer = b""
        deadline = time.monotonic() + TIMEOUT
        while not answer.endswith(b"\n") and time.monotonic() < deadline and server.poll() is None:
            ready, _, _ = select.select([read_end], [], [], 0.2)
            if ready:
                chunk = os.read(read_end, 16)
                if not chunk:
                    break
                answer += chunk
        os.close(read_end)
        display = ":%d" % number
        probe = subprocess.run(["xdotool", "getdisplaygeometry"], env={**os.environ, "DISPLAY": display},
                               capture_output=True, text=True)
        if answer.strip() == str(number).encode() and probe.stdout.split() == ["1280", "800"]:
            os.environ["DISPLAY"] = display
            return server
        server.kill()
        server.wait()
    fail("could not start Xvfb")


def main():
    global XVFB
    arguments = [a for a in sys.argv[1:] if not a.startswith("--")]
    only = [a[len("--only="):] for a in sys.argv[1:] if a.startswith("--only=")]
    if len(arguments) not in (1, 2):
        print(__doc__)
        return 2
    binary = os.path.abspath(arguments[0])
    amls = os.path.abspath(arguments[1]) if len(arguments) == 2 else None
    if not shutil.which("xdotool") or not (shutil.which("Xvfb") or os.environ.get("DISPLAY")):
        print("skipped: needs xdotool and Xvfb (or an X display)")
        return 77
    # AMLS_GUI_TEST_KEEP=1 keeps the folder (logs, exports, screenshot) for a look after a failure.
    folder = tempfile.mkdtemp(prefix="amls-editor-gui-")
    print("files in " + folder, flush=True)
    try:
        if shutil.which("Xvfb"):
            XVFB = start_xvfb(os.path.join(folder, "xvfb.log"))
        begin = time.monotonic()
        tests = {"2d": lambda: test_2d(binary, folder),
                 "open_without_normals": lambda: test_open_without_normals(binary, folder),
                 "regions": lambda: test_regions(binary, folder, amls),
                 "region_edits": lambda: test_region_edits(binary, folder),
                 "frames_during_heavy_step": lambda: test_frames_during_heavy_step(binary, folder),
                 "open_cap_drag": lambda: test_open_cap_drag(binary, folder, amls)}
        for name in only or tests:
            tests[name]()
        print("all GUI checks passed in %.1f s" % (time.monotonic() - begin))
    finally:
        if XVFB:
            XVFB.terminate()
            XVFB.wait()
        if not os.environ.get("AMLS_GUI_TEST_KEEP"):
            shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
