#!/usr/bin/env python3
# view.py -- `make bench`'s live-viewer section: how soon a page has its
# first picture, how many pictures a second it gets while shooting, and
# how soon a moved object's first redistributed picture comes, measured
# from an HTTP client on the same machine (the browser's own drawing time
# is not in these figures).  Prints figures; asserts nothing.
# Usage: bench/view.py RADIOSITY ASSETS SCENE OBJECT [ROUNDS]
#   SCENE with an object OBJECT that `move OBJECT 40 0 0` moves (the
#   moving Cornell box: data/cornell-moving-box.scene box).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
import http.client
import json
import select
import statistics
import subprocess
import sys
import time

RAD, ASSETS, SCENE, OBJ = sys.argv[1:5]
ROUNDS = int(sys.argv[5]) if len(sys.argv) > 5 else 3


def start():
    p = subprocess.Popen([RAD, "view", "-q", "--paused", "--assets", ASSETS, SCENE],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    t = time.time()
    ready, _, _ = select.select([p.stdout], [], [], 600)
    url = p.stdout.readline().decode().strip() if ready else ""
    host, port = url.split("//")[1].rstrip("/").rsplit(":", 1)
    return p, host, int(port), time.time() - t


def get(host, port, path, method="GET", body=None):
    c = http.client.HTTPConnection(host, port, timeout=600)
    c.request(method, path, body=body)
    r = c.getresponse()
    data = r.read()
    c.close()
    return data


def stream(host, port):
    c = http.client.HTTPConnection(host, port, timeout=600)
    c.request("GET", "/api/events")
    return c.getresponse()


def next_state(r):
    while True:
        line = r.fp.readline()
        if not line:
            return None
        if line.startswith(b"data: "):
            return json.loads(line[6:])


def one_round():
    p, host, port, t_start = start()
    t0 = time.time()
    get(host, port, "/")
    get(host, port, "/view.js")
    get(host, port, "/api/scene")
    ev = stream(host, port)
    next_state(ev)
    t_first = time.time() - t0
    get(host, port, "/api/control?action=run&rate=0", "POST")
    next_state(ev)
    t1, k = time.time(), 0
    while time.time() - t1 < 3:
        next_state(ev)
        k += 1
    rate = k / (time.time() - t1)
    get(host, port, "/api/control?action=pause", "POST")
    while json.loads(get(host, port, "/api/state"))["changes"] == "building":
        time.sleep(0.05)
    t2 = time.time()
    get(host, port, "/api/change", "POST", ("move %s 40 0 0" % OBJ).encode())
    while True:  # the direct light's change all shot (or the frame done)
        s = next_state(ev)
        if s["mode"] == "animate" and (s["frame_stage"] != "direct" or s["frame"] >= 1):
            break
    t_moved = time.time() - t2
    while s["frame"] < 1:
        s = next_state(ev)
    t_frame = time.time() - t2
    ev.close()
    get(host, port, "/api/control?action=stop", "POST")
    p.wait(60)
    return t_start, t_first, rate, t_moved, t_frame


rows = [one_round() for _ in range(ROUNDS)]
med = [statistics.median(c) for c in zip(*rows)]
print("   solve before serving %.2f s; page, scene and first state %.3f s (target 1 s)"
      % (med[0], med[1]))
print("   pictures a second while shooting unpaced: %.0f (target at least 20)" % med[2])
print("   move %s: first redistributed picture (the direct light's change) %.3f s "
      "(target 0.5 s), frame converged %.3f s" % (OBJ, med[3], med[4]))
print("   (medians of %d rounds)" % ROUNDS)
