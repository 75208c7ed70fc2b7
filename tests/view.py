#!/usr/bin/env python3
# view.py -- `radiosity view` through its HTTP requests, as a page and a
# hostile client meet it: the numbers it streams against independent ones,
# every class of bad request refused with the state unchanged, and a clean
# stop.  Prints TAP lines for view.sh.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
#
# Usage: view.py RADIOSITY ASSETS WORKDIR
#
# References, never the server's own earlier output:
#   - a fresh `radiosity solve` of the same scene (gauss): the element
#     radiosity the server reaches after running to convergence, within
#     1e-9 of it relative to the largest B;
#   - one sorted shot from B = E, computed here from `radiosity formfactor`'s
#     F (Cohen et al. 1988, eq. 5: B_j += rho_j E_s F_js from the one
#     emitter s): within 1e-12 relative (the same F; the sums differ only
#     in the order of two terms);
#   - eq. 14 of B = E against the solve's B, computed here from the element
#     table's areas: the server's rms at step 0 within 1e-12 relative.
import http.client
import json
import os
import select
import signal
import socket
import subprocess
import sys
import threading
import time

RAD, ASSETS, WORK = sys.argv[1], sys.argv[2], sys.argv[3]
n_checks = 0
failed = 0


def ok(cond, what):
    global n_checks, failed
    n_checks += 1
    print(("ok %d - %s" if cond else "not ok %d - %s") % (n_checks, what), flush=True)
    if not cond:
        failed += 1


SCENE = """# an open room: a white floor and back wall, red and green sides, a lamp
material white reflect 0.7 0.7 0.7
material red reflect 0.6 0.1 0.1
material green reflect 0.1 0.6 0.1
material lamp reflect 0 emit 1 0.9 0.8
quad white  0 0 0  0 0 1  1 0 1  1 0 0  mesh 3x3
quad lamp   0 1 0  1 1 0  1 1 1  0 1 1  mesh 1x1
quad white  0 0 1  0 1 1  1 1 1  1 0 1  mesh 3x3
quad red    0 0 0  0 1 0  0 1 1  0 0 1  mesh 3x3
quad green  1 0 0  1 0 1  1 1 1  1 1 0  mesh 3x3
camera eye 0.5 0.5 -1.2 at 0.5 0.5 0.5 up 0 1 0 fov 50
"""
scene = os.path.join(WORK, "room.scene")
with open(scene, "w") as f:
    f.write(SCENE)


def table(path):
    with open(path) as f:
        head = f.readline().rstrip("\n").split("\t")
        return [dict(zip(head, line.rstrip("\n").split("\t"))) for line in f]


def start(*extra, env=None, sigint=False):
    """sigint: the server gets SIGINT's default disposition even when this
    suite was started with it ignored (a background job's, which the
    program rightly keeps), so that the Ctrl-C check tests the program."""
    args = list(extra) if extra and extra[-1].endswith(".scene") else list(extra) + [scene]
    pre = (lambda: signal.signal(signal.SIGINT, signal.SIG_DFL)) if sigint else None
    p = subprocess.Popen([RAD, "view", "-q", "--paused", "--assets", ASSETS, *args],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, preexec_fn=pre)
    ready, _, _ = select.select([p.stdout], [], [], 120)
    url = p.stdout.readline().decode().strip() if ready else ""
    return p, url


class Client:
    def __init__(self, url):
        hostport = url.split("//")[1].rstrip("/")
        self.host, port = hostport.rsplit(":", 1)
        self.port = int(port)

    def req(self, method, path, body=None, headers=None):
        c = http.client.HTTPConnection(self.host, self.port, timeout=30)
        h = dict(headers or {})
        c.request(method, path, body=body, headers=h)
        r = c.getresponse()
        data = r.read()
        c.close()
        return r.status, data

    def json(self, path):
        status, data = self.req("GET", path)
        return json.loads(data) if status == 200 else None

    def control(self, query):
        return self.req("POST", "/api/control?" + query)

    def wait_step(self, step, limit=60):
        t = time.time()
        while time.time() - t < limit:
            s = self.json("/api/state")
            if s["step"] >= step and not s["busy"]:
                return s
            time.sleep(0.02)
        return None


# ---- references ---------------------------------------------------------
subprocess.run([RAD, "solve", "-q", scene, "--elements", os.path.join(WORK, "ref.tsv"),
                "-o", os.path.join(WORK, "ref.ply")], check=True)
ref = table(os.path.join(WORK, "ref.tsv"))
n = len(ref)
area = [float(r["area"]) for r in ref]
Bref = [[float(r[b]) for b in ("r", "g", "b")] for r in ref]
with open(os.path.join(WORK, "F.tsv"), "w") as f:
    subprocess.run([RAD, "formfactor", "-q", scene], stdout=f, check=True)
F = {}
with open(os.path.join(WORK, "F.tsv")) as f:
    f.readline()
    for line in f:
        i, j, v = line.split("\t")[:3]
        F[(int(i), int(j))] = float(v)

p, url = start()
ok(url.startswith("http://127.0.0.1:"), "the URL is printed: %s" % url)
cl = Client(url)

# ---- what the page loads --------------------------------------------------
status, page = cl.req("GET", "/")
with open(os.path.join(ASSETS, "index.html"), "rb") as f:
    ok(status == 200 and page == f.read(), "GET / serves index.html as it is")
status, js = cl.req("GET", "/view.js")
with open(os.path.join(ASSETS, "view.js"), "rb") as f:
    ok(status == 200 and js == f.read(), "GET /view.js serves view.js as it is")
sc = cl.json("/api/scene")
ok(sc is not None and sc["elements"] == n and len(sc["faces"]) == n,
   "the scene has the solve's %d elements" % n)
ok(sc["camera"]["fov"] == 50 and sc["camera"]["eye"] == [0.5, 0.5, -1.2],
   "the scene's camera is the file's")
ok(sum(sc["emits"]) == 1 and sc["emits"][9] == 1, "one element emits: the lamp, element 9")

# ---- step 0 and one shot --------------------------------------------------
s0 = cl.json("/api/elements")
E = [[float(x) for x in s0["element_b"][3 * i:3 * i + 3]] for i in range(n)]
tot = sum(area)
rms = (sum(a * (sum(e) / 3 - sum(b) / 3) ** 2 for a, e, b in zip(area, E, Bref)) / tot) ** 0.5
ok(s0["step"] == 0 and abs(s0["rms"] - rms) <= 1e-12 * rms,
   "step 0: eq. 14 of B = E is %.17g (here: %.17g)" % (s0["rms"], rms))
status, _ = cl.control("action=reset&method=sorted")
ok(status == 200, "reset to sorted")
cl.wait_step(0)
status, _ = cl.control("action=step")
s1 = cl.wait_step(1)
ok(s1 is not None and s1["step"] == 1 and s1["shooter"] == 9, "one sorted shot: the lamp shot")
e1 = cl.json("/api/elements")["element_b"]
rho = {"white": (0.7, 0.7, 0.7), "red": (0.6, 0.1, 0.1), "green": (0.1, 0.6, 0.1),
       "lamp": (0, 0, 0)}
mat = ["white"] * 9 + ["lamp"] + ["white"] * 9 + ["red"] * 9 + ["green"] * 9
Es = (1, 0.9, 0.8)
worst = 0
for j in range(n):
    for b in range(3):
        want = (Es[b] if j == 9 else 0) + rho[mat[j]][b] * Es[b] * F.get((j, 9), 0)
        worst = max(worst, abs(e1[3 * j + b] - want))
ok(worst <= 1e-12, "after one shot B_j = E_j + rho_j E_lamp F_j,lamp (worst %.3g)" % worst)
ok(e1 is not None and s1["unshot"] < 1, "unshot power fell below the emitted: %s" % s1["unshot"])

# ---- two clients see the same state -------------------------------------
def events(out, step, key="step", timeout=30):
    """The stream's states until one whose `key` reaches `step` (or the
    stream ends)."""
    c = http.client.HTTPConnection(cl.host, cl.port, timeout=timeout)
    c.request("GET", "/api/events")
    r = c.getresponse()
    while not out or out[-1][key] < step:
        line = r.fp.readline()
        if not line:
            break
        if line.startswith(b"data: "):
            out.append(json.loads(line[6:]))
    c.close()


a_ev, b_ev = [], []
ta = threading.Thread(target=events, args=(a_ev, 3))
tb = threading.Thread(target=events, args=(b_ev, 3))
ta.start()
tb.start()
time.sleep(0.3)
cl.control("action=step&steps=2")
ta.join(30)
tb.join(30)
ok(a_ev and b_ev and a_ev[-1]["step"] == b_ev[-1]["step"] == 3 and
   a_ev[-1]["vertex_b"] == b_ev[-1]["vertex_b"],
   "two streams see the same state: step %s" % (a_ev[-1]["step"] if a_ev else None))

# ---- the race: four methods side by side ----------------------------------
# `radiosity progress` runs the four methods of figure 7 one after the
# other (progressive.c's race); the viewer steps them together (its
# stepper): after 30 steps each lane's eq. 14 error is progress's row 30
status, _ = cl.control("action=reset&method=race")
cl.wait_step(0)
cl.control("action=step&steps=30")
st = cl.wait_step(30)
with open(os.path.join(WORK, "race.tsv"), "w") as f:
    subprocess.run([RAD, "progress", "-q", "--steps", "30", scene], stdout=f, check=True)
rows = table(os.path.join(WORK, "race.tsv"))
os.remove(os.path.join(WORK, "race.tsv"))
lanes = st.get("race", []) if st else []
want = {m: float(rows[30][m]) for m in ("gathering", "shooting", "sorted", "sorted_ambient")}
ok(st is not None and st["method"] == "race" and [l["method"] for l in lanes] ==
   list(want) and all(abs(l["rms"] - want[l["method"]]) <= 1e-12 * want[l["method"]]
                      for l in lanes) and len(st["rms_history"][-1]) == 5,
   "race, 30 steps: each lane's eq. 14 is progress's (%s)" %
   " ".join("%.6g" % l["rms"] for l in lanes))
ok(all(len(l["vertex_b"]) == len(st["vertex_b"]) for l in lanes) and
   lanes[0]["vertex_b"] == st["vertex_b"], "each lane has the vertex radiosity")

# ---- a row of F for the heat map ------------------------------------------
row = cl.json("/api/row?element=0")
worst = max(abs(row["row"][j] - F.get((0, j), 0.0)) for j in range(n))
ok(row["element"] == 0 and len(row["row"]) == n and worst <= 1e-15,
   "/api/row?element=0 is row 0 of formfactor's F (worst %.3g)" % worst)
for q in ("element=-1", "element=37", "element=abc", "element=1&x=2", "", "element=1e0"):
    status, data = cl.req("GET", "/api/row?" + q)
    ok(status == 400 and b"element=I" in data, "/api/row?%s: %d" % (q, status))

# ---- the hemicube of an element --------------------------------------------
# its row against formfactor --form-factors-method hemicube at the same
# resolution, and its pixels against its row: an element is seen by some
# pixel exactly when its F_ij is positive
with open(os.path.join(WORK, "hc.tsv"), "w") as f:
    subprocess.run([RAD, "formfactor", "-q", "--form-factors-method", "hemicube",
                    "--resolution", "16", scene], stdout=f, check=True)
Fh = {}
with open(os.path.join(WORK, "hc.tsv")) as f:
    f.readline()
    for line in f:
        i, j, v = line.split("\t")[:3]
        Fh[(int(i), int(j))] = float(v)
os.remove(os.path.join(WORK, "hc.tsv"))
hc = cl.json("/api/hemicube?element=4&resolution=16")
worst = max(abs(hc["row"][j] - Fh.get((4, j), 0.0)) for j in range(n))
seen = set(x for x in hc["items"] if x >= 0)
ok(len(hc["items"]) == 3 * 16 * 16 and worst <= 1e-15 and
   seen == set(j for j in range(n) if hc["row"][j] > 0),
   "/api/hemicube?element=4: formfactor's hemicube row (worst %.3g), %d elements seen"
   % (worst, len(seen)))
for q in ("element=4&resolution=15", "element=4&resolution=0", "element=4&resolution=9999",
          "element=99", "resolution=16", "element=4&resolution=16&x=1"):
    status, data = cl.req("GET", "/api/hemicube?" + q)
    ok(status == 400 and b"element=I" in data, "/api/hemicube?%s: %d" % (q, status))

# ---- converged: a fresh solve ---------------------------------------------
cl.control("action=reset&method=sorted")
cl.wait_step(0)
cl.control("action=run&rate=0")
t = time.time()
while time.time() - t < 60 and cl.json("/api/state")["unshot"] > 1e-15:
    time.sleep(0.05)
cl.control("action=pause")
time.sleep(0.2)
conv = cl.json("/api/elements")
big = max(max(b) for b in Bref)
worst = max(abs(conv["element_b"][3 * i + b] - Bref[i][b]) for i in range(n) for b in range(3))
ok(worst <= 1e-9 * big, "run to convergence: B within %.3g of a fresh solve (1e-9 of %.4g)"
   % (worst, big))
for m in ("shooting", "gathering", "jacobi", "sorted_ambient"):
    cl.control("action=reset&method=" + m)
    cl.wait_step(0)
    cl.control("action=step&steps=400")
    s = cl.wait_step(400)
    e = cl.json("/api/elements")["element_b"]
    w = max(abs(e[3 * i + b] - Bref[i][b]) for i in range(n) for b in range(3))
    ok(s is not None and s["method"] == m and w <= 1e-9 * big,
       "%s: 400 steps reach the solve within %.3g" % (m, w))

# ---- hostile requests: refused, state unchanged ---------------------------
before = cl.json("/api/elements")
bad = [
    ("POST", "/api/control?action=explode", None, {}, 400, "an unknown action"),
    ("POST", "/api/control?action=run&method=magic", None, {}, 400, "an unknown method"),
    ("POST", "/api/control?action=step&steps=nan", None, {}, 400, "a non-finite number"),
    ("POST", "/api/control?action=step&steps=inf", None, {}, 400, "an infinite number"),
    ("POST", "/api/control?action=step&steps=0", None, {}, 400, "steps out of range"),
    ("POST", "/api/control?action=step&steps=2.5", None, {}, 400, "a fractional step"),
    ("POST", "/api/control?action=run&rate=-1", None, {}, 400, "a negative rate"),
    ("POST", "/api/control?action=run&action=pause", None, {}, 400, "a repeated parameter"),
    ("POST", "/api/control?action=run&object=box", None, {}, 400, "an unknown parameter"),
    ("POST", "/api/control", None, {}, 400, "no action"),
    ("POST", "/api/control?action=run", '{"action": "run"', {}, 413, "a body (malformed JSON)"),
    ("POST", "/api/control?action=run", None, {"Origin": "http://evil.example"}, 403,
     "another site's page (Origin)"),
    ("GET", "/api/state", None, {"Host": "evil.example:80"}, 403, "another site's Host"),
    ("POST", "/api/control?action=run", None, {"Origin": "http://127.0.0.2:%d" % cl.port}, 403,
     "a page of another server on the loopback (Origin)"),
    ("POST", "/api/control?action=run%00x", None, {}, 400, "a NUL byte in a parameter"),
    ("GET", "/etc/passwd", None, {}, 404, "an unknown route"),
    ("GET", "/../index.html", None, {}, 404, "a path out of the assets"),
    ("GET", "/api/control?action=run", None, {}, 405, "GET on control"),
    ("DELETE", "/api/state", None, {}, 405, "DELETE"),
    ("POST", "/api/state", None, {}, 405, "POST on the state"),
]
for method, path, body, headers, want, what in bad:
    status, data = cl.req(method, path, body, headers)
    try:
        reason = json.loads(data)["error"]
    except Exception:
        reason = None
    ok(status == want and reason, "%s: %d %s" % (what, status, reason))

# a fuzzer of the request API (a fixed seed: the same requests every run):
# random methods, routes, query strings, headers and bodies, each invalid
# by construction (control values outside the actions and methods, JSON
# bodies that do not parse), so that none may change the state
import random
import urllib.parse
rng = random.Random(51)
ROUTES = ["/", "/view.js", "/api/scene", "/api/state", "/api/elements", "/api/row",
          "/api/hemicube", "/api/control", "/api/change", "/api/", "/api/control/x", "//",
          "/index.html/..", "/%00", "/api/state%2f..", "/" + "a" * 3000]


def junk(k):
    return "".join(rng.choice("abcXYZ019.-_~%&=;:/?#[]@!$'()*+, \t\\\"{}\x7f\u00e9")
                   for _ in range(rng.randint(0, k)))


def bad_control():
    """A query that names no valid action, or an invalid value for a good one."""
    keys = ["action", "method", "steps", "rate", junk(8)]
    q = []
    for _ in range(rng.randint(0, 4)):
        q.append((rng.choice(keys), junk(12)))
    if rng.random() < 0.5:
        q.append(("action", rng.choice(["run", "step", "reset"])))
        q.append((rng.choice(["method", "steps", "rate"]),
                  rng.choice(["", "nan", "-1", "1e999", "0x10", "2.5", "sorted ", "RACE"])))
    return urllib.parse.urlencode(q)


def bad_json():
    while True:
        body = bytearray(json.dumps({"changes": ["move box 0.1 0 0", "remove box"]}).encode())
        for _ in range(rng.randint(1, 4)):
            body[rng.randrange(len(body))] = rng.randrange(256)
        try:
            json.loads(body)
        except Exception:
            return bytes(body)


survived = True
for k in range(1500):
    route = rng.choice(ROUTES)
    method = rng.choice(["GET", "POST", "HEAD", "PUT", "DELETE", "OPTIONS", "PATCH", "GeT"])
    path = route
    if route == "/api/control":
        method = "POST" if rng.random() < 0.8 else method
        path += "?" + bad_control()
    elif rng.random() < 0.3:
        path += "?" + junk(40)
    path = urllib.parse.quote(path, safe="/?&=%")
    body, headers = None, {}
    if route == "/api/change" and method == "POST":
        body, headers = bad_json(), {"Content-Type": "application/json"}
    elif rng.random() < 0.2:
        body = junk(200).encode()
    if rng.random() < 0.2:
        headers["X-" + junk(5).replace(" ", "").replace(":", "") or "X-a"] = junk(20).replace(
            "\n", "").replace("\r", "")
    try:
        status, _ = cl.req(method, path, body, headers)
    except (http.client.HTTPException, OSError, ValueError):
        continue  # a request the client library itself refuses to send
    if status >= 500:
        survived = False
        print("# fuzz %d: %s %s -> %d" % (k, method, path[:80], status), file=sys.stderr)
ok(survived and cl.json("/api/state") is not None,
   "1,500 fuzzed requests: no 5xx, and the server answers")

# a body past the limit: the connection ends, the server lives
s = socket.create_connection((cl.host, cl.port), timeout=10)
s.sendall(b"POST /api/control?action=run HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n"
          b"Content-Length: 100000000\r\n\r\n" % cl.port)
try:
    s.sendall(b"x" * 131072) # past the limit; the rest would never be read
    answer = s.recv(4096)
except OSError:
    answer = b""
s.close()
ok(answer.startswith(b"HTTP/1.1 413") and cl.json("/api/state") is not None,
   "a 100 MB body announced: 413 after 64 KiB of it, and the server answers (%r)" % answer[:24])
# garbage instead of HTTP
s = socket.create_connection((cl.host, cl.port), timeout=10)
s.sendall(b"\x00\xff GARBAGE \r\n\r\n")
try:
    s.recv(4096)
except OSError:
    pass
s.close()
ok(cl.json("/api/state") is not None, "bytes that are not HTTP: the server answers")
# many connections at once, past the limit
socks = []
for _ in range(64):
    try:
        socks.append(socket.create_connection((cl.host, cl.port), timeout=5))
    except OSError:
        break
for k in socks:
    k.close()
time.sleep(0.5)
ok(cl.json("/api/state") is not None, "64 idle connections opened and dropped: the server answers")
after = cl.json("/api/elements")
ok(after["element_b"] == before["element_b"] and after["step"] == before["step"] and
   after["method"] == before["method"] and after["running"] == before["running"],
   "no refused request changed the state")

# ---- the stop button ------------------------------------------------------
status, _ = cl.control("action=stop")
try:
    code = p.wait(20)
except subprocess.TimeoutExpired:
    p.kill()
    code = None
ok(status == 200 and code == 0, "the stop action ends the server with status 0 (%s)" % code)

# ---- changes through the redistribution engine ----------------------------
def box(dx):
    """A box object 0.02 above the floor, at x = 0.2 + dx (faces from outside)."""
    x0, x1, y0, y1, z0, z1 = 0.2 + dx, 0.5 + dx, 0.02, 0.3, 0.3, 0.6
    q = lambda *p: "quad grey " + "  ".join("%.17g %.17g %.17g" % v for v in p) + " mesh 2x2\n"
    return ("object box\n" +
            q((x0, y1, z0), (x0, y1, z1), (x1, y1, z1), (x1, y1, z0)) +
            q((x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)) +
            q((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)) +
            q((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0)) +
            q((x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)) + "end\n")


def with_box(dx, name):
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        f.write(SCENE + "material grey reflect 0.5\n" + box(dx))
    return path


def solve_b(path):
    out = os.path.join(WORK, "s.tsv")
    subprocess.run([RAD, "solve", "-q", "--accuracy", "default", path, "--elements", out,
                    "-o", os.path.join(WORK, "s.ply")], check=True)
    rows = table(out)
    os.remove(out)
    os.remove(os.path.join(WORK, "s.ply"))
    return [float(r[b]) for r in rows for b in ("r", "g", "b")]


def close(a, b, rel):
    big = max(abs(x) for x in b)
    return len(a) == len(b) and max(abs(x - y) for x, y in zip(a, b)) <= rel * big


def wait_frame(k, limit=120):
    t = time.time()
    while time.time() - t < limit:
        s = cl.json("/api/state")
        if s["frame"] >= k and s["frames"] == s["frame"]:
            return s
        time.sleep(0.05)
    return None


boxed = with_box(0, "box.scene")
moved = with_box(0.1, "moved.scene")
record = os.path.join(WORK, "session.changes")
p, url = start("--accuracy", "default", "--record", record, boxed)
cl = Client(url)
t = time.time()
while time.time() - t < 120 and cl.json("/api/state")["changes"] == "building":
    time.sleep(0.05)
ok(cl.json("/api/state")["changes"] == "ready", "the animation is built")
seen = []
tf = threading.Thread(target=events, args=(seen, 1, "frame", 120))
tf.start()
time.sleep(0.3)
status, data = cl.req("POST", "/api/change", "move box 0.1 0 0\n")
ok(status == 200, "a move is queued: %s" % data.decode())
st = wait_frame(1)
tf.join(60)
anim = [x for x in seen if x["mode"] == "animate"]
stages = [(x["frame"], x["frame_stage"]) for x in anim]
k = stages.index((0, "form_factors")) if (0, "form_factors") in stages else -1
ok(k >= 0 and all(x == (0, "direct") for x in stages[:k]) and stages[-1] == (1, "done") and
   anim[k]["geometry"] >= 1 and anim[k]["vertex_b"] != anim[-1]["vertex_b"],
   "the move's direct light is shown on the moved box before the other form factors are "
   "computed: %s ... %s" % (stages[:k + 1], stages[-1:]))
ok(st is not None and st["mode"] == "animate" and st["converged"] and st["geometry"] >= 1,
   "frame 1 runs and converges; the picture is the animation's")
el = cl.json("/api/elements")["element_b"]
ref_moved = solve_b(moved)
ok(close(el, ref_moved, 1e-9), "the moved frame equals a fresh solve of the moved scene (1e-9)")
sc = cl.json("/api/scene")
xs = [sc["vertices"][3 * v] for f, srf in zip(sc["faces"], sc["surface"]) if srf >= 5 for v in f]
ok(abs(min(xs) - 0.3) < 1e-9 and abs(max(xs) - 0.6) < 1e-9,
   "the scene served is the moved one: the box spans x %.9g..%.9g" % (min(xs), max(xs)))
status, data = cl.control("action=run")
ok(status == 409, "the race cannot run on a changed scene: %d %s" % (status, data.decode()))
status, _ = cl.control("action=undo")
st = wait_frame(2)
el = cl.json("/api/elements")["element_b"]
ok(status == 200 and st is not None and close(el, solve_b(boxed), 1e-9),
   "undo: frame 2 equals a fresh solve of the scene as loaded")
status, data = cl.control("action=undo")
ok(status == 409, "nothing left to undo: %d %s" % (status, data.decode()))
for body, ctype, what in (
        ('{"changes": ["remove box"]}', "application/json", "JSON, an array"),
        ('"add box"', "application/json", "JSON, a string"),
        ("material grey reflect 0.2 0.3 0.4\nframe\nrotate box 0 1 0 30\n", "text/plain",
         "two frames as text")):
    status, data = cl.req("POST", "/api/change", body, {"Content-Type": ctype})
    ok(status == 200, "%s: %d %s" % (what, status, data.decode()))
st = wait_frame(6)
ok(st is not None and st["frame"] == 6, "the frames ran: %s" % (st and st["frame"]))
for body, ctype, want, what in (
        ("move nobox 1 0 0", "text/plain", b"request:1: ", "an unknown object"),
        ("move box 1 0\n", "text/plain", b"request:1: ", "a move without its z"),
        ("move box 0 0 0\nmove box nan 0 0\n", "text/plain", b"request:2: ", "a NaN on line 2"),
        ("add box", "text/plain", b"request:1: ", "adding a box that is there"),
        ("", "text/plain", b"no changes", "an empty body"),
        ('{"changes": "move box 1 0 0"', "application/json", b"JSON body", "truncated JSON"),
        ('{"moves": "move box 1 0 0"}', "application/json", b"JSON body", "another key"),
        ('["move box", 3]', "application/json", b"JSON body", "a number in the array"),
        ('"move box \\ud800 1 0 0"', "application/json", b"JSON body", "a lone surrogate"),
        ("# nothing but a comment\n\n", "text/plain", b"no change", "a comment alone"),
        # parsed, but no element of the moved box has a double's area:
        # refused before it runs, rather than failing the frame and all
        # frames after it (it did, and ended the session's changes)
        ("move box 0 0 0\nmove box 1e300 0 0\n", "text/plain",
         b"request:2: frame 7: after its changes, ", "a move out of double's range")):
    status, data = cl.req("POST", "/api/change", body, {"Content-Type": ctype})
    ok(status == 400 and want in data, "%s: %d %s" % (what, status, data.decode()))
status, data = cl.req("POST", "/api/change?x=1", "move box 0 0 0")
ok(status == 400, "a parameter on /api/change: %d %s" % (status, data.decode()))
st = cl.json("/api/state")
ok(st["frames"] == 6 and st["changes"] == "ready",
   "no refused change was queued; the session still takes changes (%s)" % st["changes"])
el6 = cl.json("/api/elements")["element_b"]
cl.control("action=stop")
ok(p.wait(60) == 0, "stopped")
with open(record) as f:
    rec = f.read()
ok(rec.count("frame\n") == 6 and rec.startswith("frame\nmove box 0.1 0 0\n"),
   "--record holds the 6 frames run")
frames = os.path.join(WORK, "frame%d.tsv")
r = subprocess.run([RAD, "animate", "-q", "--accuracy", "default", "--elements", frames, boxed,
                    record], capture_output=True)
last = table(frames % 6)
ok(r.returncode == 0 and
   [float(x[b]) for x in last for b in ("r", "g", "b")] == el6,
   "radiosity animate replays the record: frame 6 bit for bit")
for k in range(7):
    os.remove(frames % k)
for name in ("box.scene", "moved.scene", "session.changes"):
    os.remove(os.path.join(WORK, name))

# ---- a frame that fails as it runs ---------------------------------------
# Shots a frame takes on the room in default mode (`radiosity animate
# --report`): frame 0, 460; a lighter white wall after it, 385; then a
# darker red one, 325; a lamp 100 times brighter, 460, and back to its own
# light (the undo of that), 539; walls of reflectance 0.99, over 1,000.
# With --max-iterations 500 the last two fail.  A frame that fails is
# dropped, the animation goes back to the frame before it (its radiosity
# bit for bit, from the state kept before the frame; frame 0 too, which
# is converged as a fresh solve), an undo frame that fails goes back on
# the undo stack, and the session goes on taking changes (it used to end
# them: 503 until the server stopped).


def room_with(*materials):
    text = SCENE
    for m in materials:
        name = m.split()[1]
        text = "\n".join(m if line.startswith("material %s " % name) else line
                         for line in text.split("\n"))
    path = os.path.join(WORK, "room%d.scene" % len(materials))
    with open(path, "w") as f:
        f.write(text)
    return path


def wait_failure(k):
    t = time.time()
    st = cl.json("/api/state")
    while time.time() - t < 120 and not (st["changes_failure"] and st["changes"] == "ready" and
                                         "failed and was dropped" in st["changes_failure"] and
                                         ("frame %d " % k) in st["changes_failure"]):
        time.sleep(0.05)
        st = cl.json("/api/state")
    return st


bright = "".join("material %s reflect 0.99 0.99 0.99\n" % m for m in ("white", "red", "green"))
record = os.path.join(WORK, "failed.changes")
p, url = start("--accuracy", "default", "--max-iterations", "500", "--record", record)
cl = Client(url)
t = time.time()
while time.time() - t < 120 and cl.json("/api/state")["changes"] == "building":
    time.sleep(0.05)
status, _ = cl.req("POST", "/api/change", bright)
st = wait_failure(1)
why = st["changes_failure"] or ""
el0 = cl.json("/api/elements")["element_b"]
ok(status == 200 and st["changes"] == "ready" and st["frame"] == 0 and st["frames"] == 0 and
   st["converged"] and "not converged after 500 shots" in why and
   close(el0, solve_b(scene), 1e-9),
   "--max-iterations 500: frame 1 fails and is dropped; the session is back at frame 0, "
   "equal to a fresh solve (1e-9): %s" % why)
lamp = "material lamp reflect 0 emit 100 90 80"
status, _ = cl.req("POST", "/api/change", lamp + "\n")
st = wait_frame(1)
el1 = cl.json("/api/elements")["element_b"]
ok(status == 200 and st is not None and st["changes_failure"] is None and st["undo"] == 1 and
   close(el1, solve_b(room_with(lamp)), 1e-9),
   "the next change runs as frame 1 and equals a fresh solve (1e-9)")
status, _ = cl.control("action=undo")
st = wait_failure(2)
ok(status == 200 and st["frame"] == 1 and st["frames"] == 1 and st["undo"] == 1 and
   cl.json("/api/elements")["element_b"] == el1,
   "its undo fails as frame 2: dropped, frame 1's radiosity bit for bit, and the undo is "
   "on the stack again: %s" % st["changes_failure"])
lighter = "material white reflect 0.6 0.6 0.6"
status, _ = cl.req("POST", "/api/change", lighter + "\n")
st = wait_frame(2)
el2 = cl.json("/api/elements")["element_b"]
ok(status == 200 and st is not None and st["undo"] == 2 and st["changes_failure"] is None,
   "a lighter wall runs as frame 2")
status, _ = cl.req("POST", "/api/change", bright)
st = wait_failure(3)
ok(status == 200 and st["frame"] == 2 and st["frames"] == 2 and st["undo"] == 2 and
   cl.json("/api/elements")["element_b"] == el2,
   "frame 3 fails too; the radiosity is frame 2's bit for bit: %s" % st["changes_failure"])
darker = "material red reflect 0.3 0.1 0.1"
status, data = cl.req("POST", "/api/change", darker + "\n")
st = wait_frame(3)
el3 = cl.json("/api/elements")["element_b"]
ok(status == 200 and st is not None and st["converged"] and st["changes_failure"] is None and
   st["undo"] == 3 and close(el3, solve_b(room_with(lamp, lighter, darker)), 1e-9),
   "a change after it runs as frame 3 and equals a fresh solve (1e-9): %d %s"
   % (status, data.decode()))
cl.control("action=stop")
ok(p.wait(60) == 0, "stopped")
with open(record) as f:
    rec = f.read()
ok(rec == "frame\n%s\nframe\n%s\nframe\n%s\n" % (lamp, lighter, darker),
   "--record holds the frames that ran, not the dropped ones: %r" % rec)
frames = os.path.join(WORK, "frame%d.tsv")
r = subprocess.run([RAD, "animate", "-q", "--accuracy", "default", "--elements", frames, scene,
                    record], capture_output=True)
ok(r.returncode == 0 and
   [float(x[b]) for x in table(frames % 3) for b in ("r", "g", "b")] == el3,
   "radiosity animate replays that record: frame 3 bit for bit")
for k in range(4):
    os.remove(frames % k)
for name in ("failed.changes", "room1.scene", "room3.scene"):
    os.remove(os.path.join(WORK, name))

# ---- the adaptive mesh as it splits ------------------------------------------

p, url = start("--method", "adaptive", "--subdivide-threshold", "0.05")
cl = Client(url)
s0 = cl.wait_step(0)
n0 = cl.json("/api/scene")["elements"]
ok(s0 is not None and s0["method"] == "adaptive" and s0["rms"] is None and n0 == 37 and
   abs(s0["unshot"] - 1) < 1e-12,
   "adaptive: step 0 on the 37 starting elements, all the power unshot (%s), no error curve"
   % (s0 and s0["unshot"]))
status, _ = cl.req("GET", "/api/row?element=0")
status2, _ = cl.req("GET", "/api/hemicube?element=0")
ok(status == 409 and status2 == 409,
   "adaptive: rows of F and hemicubes are refused while the leaves are drawn (%d, %d)"
   % (status, status2))
cl.control("action=run&rate=0")
t = time.time()
st = cl.json("/api/state")
while time.time() - t < 120 and (st["running"] or st["step"] == 0):
    time.sleep(0.05)
    st = cl.json("/api/state")
el = cl.json("/api/elements")["element_b"]
n1 = cl.json("/api/scene")["elements"]
out = os.path.join(WORK, "adaptive.tsv")
subprocess.run([RAD, "solve", "-q", "--solver", "progressive", "--adaptive",
                "--subdivide-threshold", "0.05", "--elements", out, "-o",
                os.path.join(WORK, "adaptive.ply"), scene], check=True)
rows = table(out)
ref = [float(r[b]) for r in rows for b in ("r", "g", "b")]
g1 = cl.json("/api/scene")["geometry"]
ok(g1 == st["geometry"], "adaptive: the scene served carries the state's geometry (%s, %s)"
   % (g1, st["geometry"]))
ok(not st["running"] and not st["failure"] and st["geometry"] > s0["geometry"] and
   n1 == len(rows) > n0 and el == ref,
   "adaptive: converged at step %d on %d elements split from %d; leaves and B are those of "
   "solve --adaptive, bit for bit" % (st["step"], n1, n0))
cl.control("action=reset&method=sorted")
s1 = cl.wait_step(0)
status, _ = cl.req("GET", "/api/row?element=0")
sc1 = cl.json("/api/scene")
ok(s1["method"] == "sorted" and sc1["elements"] == n0 and status == 200 and
   sc1["geometry"] == cl.json("/api/state")["geometry"],
   "adaptive, then sorted: the mesh as loaded is drawn again, its rows served, the "
   "geometry numbers agree")
cl.control("action=stop")
ok(p.wait(60) == 0, "stopped")
# a change while the adaptive mesh is drawn: the animation's picture takes over
boxed = with_box(0, "box.scene")
p, url = start("--method", "adaptive", "--accuracy", "default", boxed)
cl = Client(url)
cl.control("action=step&steps=3")
cl.wait_step(3)
t = time.time()
while time.time() - t < 120 and cl.json("/api/state")["changes"] == "building":
    time.sleep(0.05)
status, _ = cl.req("POST", "/api/change", "move box 0.1 0 0\n")
st = wait_frame(1)
status2, _ = cl.req("GET", "/api/row?element=0")
status3, _ = cl.control("action=reset&method=adaptive")
sc = cl.json("/api/scene")
el = cl.json("/api/elements")["element_b"]
ok(status == 200 and st is not None and st["mode"] == "animate" and status2 == 200 and
   status3 == 409 and sc["geometry"] == st["geometry"] and
   close(el, solve_b(with_box(0.1, "moved.scene")), 1e-9),
   "adaptive, then a move: the frame equals a fresh solve, the animation's mesh is drawn, "
   "rows are served again (%s), methods refused (%s)" % (status2, status3))
cl.control("action=stop")
ok(p.wait(60) == 0, "stopped")
for name in ("box.scene", "moved.scene"):
    os.remove(os.path.join(WORK, name))
for name in ("adaptive.tsv", "adaptive.ply"):
    os.remove(os.path.join(WORK, name))

# ---- Ctrl-C ---------------------------------------------------------------
p, url = start("--listen", "127.0.0.1:0", sigint=True)
cl = Client(url)
holder = []
t = threading.Thread(target=events, args=(holder, 10 ** 9))
t.start()
time.sleep(0.3)
p.send_signal(signal.SIGINT)
try:
    code = p.wait(20)
except subprocess.TimeoutExpired:
    p.kill()
    code = None
t.join(20)
ok(code == 0 and not t.is_alive(), "SIGINT with a stream open: status 0, the stream ends")
ok(sorted(os.listdir(WORK)) == sorted(["F.tsv", "ref.ply", "ref.tsv", "room.scene"]),
   "no file was written")

# ---- streams leave connections to the controls ---------------------------
p, url = start("--max-connections", "6")
cl = Client(url)
held = []
for _ in range(2):
    c = http.client.HTTPConnection(cl.host, cl.port, timeout=30)
    c.request("GET", "/api/events")
    held.append((c, c.getresponse()))
status, data = cl.req("GET", "/api/events")
st2, _ = cl.req("POST", "/api/control?action=step")
ok(all(r.status == 200 for _, r in held) and status == 503 and st2 == 200,
   "--max-connections 6: 2 streams, a third refused (%d), a control still served" % status)
for c, _ in held:
    c.close()
cl.control("action=stop")
p.wait(60)

# ---- --open without a browser to start ------------------------------------
bin_dir = os.path.join(WORK, "bin")
os.mkdir(bin_dir)
p, url = start("--open", env={"PATH": bin_dir})
cl = Client(url)
status, _ = cl.req("GET", "/api/state")
cl.control("action=stop")
code = p.wait(60)
err = p.stderr.read().decode()
ok(status == 200 and code == 0 and "cannot start a browser (xdg-open" in err and url in err,
   "--open without xdg-open: a warning naming the URL, and the server serves (%s)"
   % err.strip())
# ... and with one: it is started with the URL
with open(os.path.join(bin_dir, "xdg-open"), "w") as f:
    f.write("#!/bin/sh\necho \"$1\" > %s/opened\n" % WORK)
os.chmod(os.path.join(bin_dir, "xdg-open"), 0o755)
p, url = start("--open", env={"PATH": bin_dir + ":/usr/bin:/bin"})
t = time.time()
while time.time() - t < 10 and not os.path.exists(os.path.join(WORK, "opened")):
    time.sleep(0.05)
Client(url).control("action=stop")
p.wait(60)
with open(os.path.join(WORK, "opened")) as f:
    ok(f.read().strip() == url, "--open starts xdg-open with the URL")
os.remove(os.path.join(WORK, "opened"))
os.remove(os.path.join(bin_dir, "xdg-open"))
os.rmdir(bin_dir)

# ---- the command line -----------------------------------------------------
sock = socket.socket()
sock.bind(("127.0.0.1", 0))
sock.listen(1)
busy = sock.getsockname()[1]
r = subprocess.run([RAD, "view", "-q", "--listen", "127.0.0.1:%d" % busy, "--assets", ASSETS,
                    scene], capture_output=True, timeout=120)
sock.close()
ok(r.returncode == 1 and b"cannot listen on 127.0.0.1:%d" % busy in r.stderr,
   "a port in use: %s" % r.stderr.decode().strip())
for args, what in ((["--listen", "nowhere"], "--listen without a port"),
                   (["--listen", "1.2.3:99999"], "--listen with a port out of range"),
                   (["--method", "magic"], "an unknown --method"),
                   (["--rate", "-3"], "a negative --rate")):
    r = subprocess.run([RAD, "view", *args, scene], capture_output=True, timeout=60)
    ok(r.returncode == 2 and r.stderr.startswith(b"radiosity: "),
       "%s: exit %d, %s" % (what, r.returncode, r.stderr.decode().splitlines()[0]))
r = subprocess.run([RAD, "view", "-q", "--assets", os.path.join(WORK, "none"), scene],
                   capture_output=True, timeout=120)
ok(r.returncode == 1 and b"index.html" in r.stderr,
   "a missing page: %s" % r.stderr.decode().strip())
print("1..%d" % n_checks)
sys.exit(1 if failed else 0)
