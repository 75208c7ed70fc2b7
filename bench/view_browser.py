#!/usr/bin/env python3
# view_browser.py -- `make bench`'s live viewer in a real browser: how
# soon the page has its first picture after it starts to open, in
# headless Chromium (Debian's; WebGL on SwiftShader, the CPU), driven over
# the DevTools protocol (tests/cdp.py).  The times are the page's own
# (window.radiosityTiming: performance.now() at its script, its scene and
# its first picture drawn, in ms from the navigation's start).  "Cold" is
# the first page a fresh browser opens (its GPU process and shader
# compiler start then), "warm" the same page opened again in that
# browser.  Prints figures; asserts nothing.
# Usage: bench/view_browser.py RADIOSITY ASSETS SCENE WORKDIR [ROUNDS [CHROMIUM]]
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
import os
import select
import shutil
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
import cdp  # noqa: E402

RAD, ASSETS, SCENE, WORK = sys.argv[1:5]
ROUNDS = int(sys.argv[5]) if len(sys.argv) > 5 else 3
CHROMIUM = sys.argv[6] if len(sys.argv) > 6 else "chromium"


def server():
    p = subprocess.Popen([RAD, "view", "-q", "--paused", "--assets", ASSETS, SCENE],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    ready, _, _ = select.select([p.stdout], [], [], 600)
    return p, p.stdout.readline().decode().strip() if ready else ""


# The browser's own floor: a page that only makes a WebGL context,
# compiles the smallest program and draws one triangle (read back, so that
# it is done), with nothing to fetch.
FLOOR = ("data:text/html,<canvas id=c width=800 height=600></canvas><script>"
         "const g=document.getElementById('c').getContext('webgl');"
         "const s=(t,x)=>{const o=g.createShader(t);g.shaderSource(o,x);g.compileShader(o);"
         "return o};const p=g.createProgram();"
         "g.attachShader(p,s(g.VERTEX_SHADER,'attribute vec2 a;void main(){gl_Position="
         "vec4(a,0.,1.);}'));g.attachShader(p,s(g.FRAGMENT_SHADER,'void main(){gl_FragColor="
         "vec4(1.);}'));g.linkProgram(p);g.useProgram(p);const b=g.createBuffer();"
         "g.bindBuffer(g.ARRAY_BUFFER,b);g.bufferData(g.ARRAY_BUFFER,new Float32Array("
         "[0,0,1,0,0,1]),g.STATIC_DRAW);g.enableVertexAttribArray(0);"
         "g.vertexAttribPointer(0,2,g.FLOAT,false,0,0);g.drawArrays(g.TRIANGLES,0,3);"
         "g.readPixels(0,0,1,1,g.RGBA,g.UNSIGNED_BYTE,new Uint8Array(4));"
         "window.radiosityTiming={script:0,scene:0,gl:0,state:0,picture:performance.now()};"
         "</script>")


def opened(b, url):
    """Open url; the page's timing once it has drawn its first picture."""
    b.call("Page.navigate", {"url": url}, session=True)
    t = time.time()
    while time.time() - t < 60:
        try:
            tm = b.js("window.radiosityTiming && window.radiosityTiming.picture !== null "
                      "? window.radiosityTiming : null")
        except RuntimeError:
            tm = None  # the old page is going
        if tm:
            return tm
        time.sleep(0.02)
    return None


if shutil.which(CHROMIUM) is None:
    print("   (no %s: the browser's first picture is not measured)" % CHROMIUM)
    sys.exit(0)
p, url = server()
if not url:
    p.kill()
    print("   (the server did not start)")
    sys.exit(0)
cold, warm, floor = [], [], []
try:
    for k in range(ROUNDS):
        profile = os.path.join(WORK, "chrome%d" % k)
        b = cdp.Browser(CHROMIUM, profile, 1100, 900)
        try:
            first = opened(b, url)
            again = [opened(b, url + "?again=%d" % j) for j in range(3)]
        finally:
            b.close()
            shutil.rmtree(profile, ignore_errors=True)
        b = cdp.Browser(CHROMIUM, profile, 1100, 900)
        try:
            least = opened(b, FLOOR)
            if least:
                floor.append(least["picture"] / 1000)
        finally:
            b.close()
            shutil.rmtree(profile, ignore_errors=True)
        if first and all(again):
            cold.append(first)
            warm.extend(again)
finally:
    subprocess.run([sys.executable, "-c", "import http.client as h, sys; "
                    "c = h.HTTPConnection(sys.argv[1], int(sys.argv[2]), timeout=10); "
                    "c.request('POST', '/api/control?action=stop'); c.getresponse()",
                    *url.split("//")[1].rstrip("/").rsplit(":", 1)], check=False)
    try:
        p.wait(60)
    except subprocess.TimeoutExpired:
        p.kill()
if not cold:
    print("   (the browser drew no picture)")
    sys.exit(0)


def med(rows, key):
    return statistics.median(r[key] for r in rows) / 1000


for name, rows in (("cold", cold), ("warm", warm)):
    print("   browser, %s: script %.2f s, scene %.2f s, WebGL %.2f s, state %.2f s, first "
          "picture %.2f s after the page began to open%s"
          % (name, med(rows, "script"), med(rows, "scene"), med(rows, "gl"), med(rows, "state"),
             med(rows, "picture"), " (target 1 s)" if name == "cold" else ""))
if floor:
    print("   the browser's floor, cold: one WebGL triangle drawn and read back %.2f s after "
          "a page with nothing to fetch began to open (the page's own figures are taken when "
          "its draw is issued, a little earlier than done)" % statistics.median(floor))
print("   (medians: %d fresh browsers, %d pages opened again)" % (len(cold), len(warm)))
