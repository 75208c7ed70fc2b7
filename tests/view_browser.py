#!/usr/bin/env python3
# view_browser.py -- the viewer's page in a real browser: headless
# Chromium (Debian's) opens the live page against a server on the moving
# Cornell box, and the page's own controls step the solver and move the
# box.  Prints TAP lines for viewer.sh.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: view_browser.py RADIOSITY ASSETS SCENE WORKDIR [CHROMIUM]
#
# References, never the page's own earlier output:
#   - `radiosity progress --snapshots-at 40`'s picture of sorted_ambient
#     after 40 shots (the renderer, the converged solution's exposure): the
#     canvas after the page's Step button took 40 shots matches it but for
#     pixels whose centre lies on an edge, where the renderer's double
#     rounding decides a tie that no GPU reproduces: at most 0.1% of the
#     pixels may differ by more than 1 in a channel (8-bit rounding);
#   - a fresh `radiosity solve` of the scene with the box moved 80 along x
#     (written here): the frame the page's "+x" button reaches, twice at
#     step 40, within 1e-9 of it relative to the largest B (the server's
#     element table, numbered as a fresh solve numbers it).
# The browser is driven by the DevTools protocol over a pipe
# (--remote-debugging-pipe: JSON messages ended by a NUL byte on fds 3 and
# 4), so no extra package is needed; console errors fail the run.
import base64
import http.client
import json
import os
import re
import select
import struct
import subprocess
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cdp  # noqa: E402

RAD, ASSETS, SCENE, WORK = sys.argv[1:5]
CHROMIUM = sys.argv[5] if len(sys.argv) > 5 else "chromium"
MESH_ARGS = []
n_checks = failed = 0


def ok(cond, what):
    global n_checks, failed
    n_checks += 1
    print(("ok %d - %s" if cond else "not ok %d - %s") % (n_checks, what), flush=True)
    failed += 0 if cond else 1


def png_rgb(data):
    """8-bit RGB or RGBA, non-interlaced PNG -> (w, h, rows of RGB bytes)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, lace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and ctype in (2, 6) and lace == 0
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(w * bpp)
    stride = w * bpp
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):  # the five filters of PNG (RFC 2083, 6)
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[i] for i in range(stride) if bpp == 3 or i % 4 != 3))
        prev = line
    return w, h, rows


def server():
    p = subprocess.Popen([RAD, "view", "-q", "--paused", "--assets", ASSETS, *MESH_ARGS, SCENE],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    ready, _, _ = select.select([p.stdout], [], [], 300)
    return p, p.stdout.readline().decode().strip() if ready else ""


def api(url, path, method="GET"):
    host, port = url.split("//")[1].rstrip("/").rsplit(":", 1)
    c = http.client.HTTPConnection(host, int(port), timeout=120)
    c.request(method, path)
    data = c.getresponse().read()
    c.close()
    return json.loads(data)


def moved_scene(path, dx):
    """The scene file with every vertex of object `box` moved dx along x."""
    out, inside = [], False
    with open(SCENE) as f:
        for line in f:
            words = line.split()
            if words[:2] == ["object", "box"]:
                inside = True
            elif words[:1] == ["end"]:
                inside = False
            elif inside and words[:1] == ["quad"]:
                nums = [float(w) for w in words[2:14]]
                for k in range(0, 12, 3):
                    nums[k] += dx
                line = " ".join(words[:2] + ["%.17g" % x for x in nums] + words[14:]) + "\n"
            out.append(line)
    with open(path, "w") as f:
        f.writelines(out)


def table_b(path):
    with open(path) as f:
        head = f.readline().rstrip("\n").split("\t")
        rows = [dict(zip(head, l.rstrip("\n").split("\t"))) for l in f]
    return [float(r[b]) for r in rows for b in ("r", "g", "b")]


def compare(a, b):
    """(pixels, pixels differing by more than 1, largest difference)."""
    (wa, ha, ra), (wb, hb, rb) = a, b
    if (wa, ha) != (wb, hb):
        return wa * ha, wa * ha, 255
    over, worst = 0, 0
    for y in range(ha):
        d = max((abs(p - q) for p, q in zip(ra[y], rb[y])), default=0)
        worst = max(worst, d)
        if d > 1:
            over += sum(1 for x in range(wa)
                        if max(abs(ra[y][3 * x + c] - rb[y][3 * x + c]) for c in range(3)) > 1)
    return wa * ha, over, worst


# ---- references ------------------------------------------------------------
subprocess.run([RAD, "progress", "-q", "--steps", "40", "--snapshots-at", "40",
                "--snapshot-prefix", os.path.join(WORK, "p"), *MESH_ARGS, SCENE],
               stdout=subprocess.DEVNULL, check=True)
with open(os.path.join(WORK, "p-sorted_ambient-000040.png"), "rb") as f:
    ref40 = png_rgb(f.read())
moved = os.path.join(WORK, "moved.scene")
moved_scene(moved, 80)
subprocess.run([RAD, "solve", "-q", *MESH_ARGS, moved, "--elements",
                os.path.join(WORK, "moved.tsv"), "-o", os.path.join(WORK, "moved.ply")],
               check=True)
want = table_b(os.path.join(WORK, "moved.tsv"))

# ---- the page, live ----------------------------------------------------------
p, url = server()
ok(url.startswith("http://127.0.0.1:"), "the server is up: %s" % url)
b = cdp.Browser(CHROMIUM, WORK + "/chrome", 1100, 900)
b.call("Page.navigate", {"url": url}, session=True)
ok(b.wait("document.getElementById('state-step') && "
          "document.getElementById('state-step').textContent.trim() === '0'"),
   "the page shows step 0 from the stream")
b.js("document.getElementById('steps').value = '40'; document.getElementById('step').click()")
st = None
t = time.time()
while time.time() - t < 120:
    st = api(url, "/api/state")
    if st["step"] == 40 and not st["busy"]:
        break
    time.sleep(0.05)
ok(st["step"] == 40 and st["method"] == "sorted_ambient",
   "the page's Step button took 40 shots (%s, step %s)" % (st["method"], st["step"]))
ok(b.wait("document.getElementById('state-step').textContent.trim() === '40'"),
   "the page shows step 40")
b.js("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
rect = b.js("(() => { const r = document.getElementById('scene').getBoundingClientRect();"
            " return [r.left, r.top, r.width, r.height]; })()")
shot = b.call("Page.captureScreenshot", {"format": "png", "clip": {
    "x": rect[0], "y": rect[1], "width": rect[2], "height": rect[3], "scale": 1}}, session=True)
got = png_rgb(base64.b64decode(shot["data"]))
total, over, worst = compare(got, ref40)
ok(total == ref40[0] * ref40[1] and over <= 0.001 * total,
   "the canvas after 40 shots is progress's picture: %d of %d pixels differ by more than 1 "
   "(largest %d)" % (over, total, worst))

# ---- the box moved by the page's own controls --------------------------------
ok(b.wait("document.getElementById('changes') && !document.getElementById('changes').hidden "
          "&& document.getElementById('object').value === 'box' && "
          "!document.getElementById('object-tools').disabled", 300),
   "the page offers the object box")
t = time.time()
while time.time() - t < 300 and api(url, "/api/state")["changes"] == "building":
    time.sleep(0.1)
for k in (1, 2):
    b.js("document.getElementById('move-step').value = '40';"
         "document.getElementById('move-xp').click()")
    t = time.time()
    while time.time() - t < 300:
        st = api(url, "/api/state")
        if st["frame"] >= k and st["frames"] == st["frame"]:
            break
        time.sleep(0.05)
ok(st["mode"] == "animate" and st["frame"] == 2 and st["converged"],
   "two clicks on +x at step 40: two frames run and converged")
el = api(url, "/api/elements")["element_b"]
big = max(abs(x) for x in want)
worst = max(abs(x - y) for x, y in zip(el, want)) if len(el) == len(want) else float("inf")
ok(worst <= 1e-9 * big, "the frame is a fresh solve of the box moved 80 along x: %.3g "
   "(1e-9 of %.4g)" % (worst, big))
ok(b.wait("document.getElementById('undo') && !document.getElementById('undo').disabled"),
   "the page offers undo")
errs = b.errors()
ok(not errs, "no error in the page's console %s" % errs[:3])
b.close()
api(url, "/api/control?action=stop", "POST")
ok(p.wait(60) == 0, "the server stops")
print("1..%d" % n_checks)
sys.exit(1 if failed else 0)
