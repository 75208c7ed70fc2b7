# cdp.py -- headless Chromium driven by the DevTools protocol over a pipe
# (--remote-debugging-pipe: JSON messages ended by a NUL byte on fds 3 and
# 4), so that no package beyond Debian's chromium is needed: the viewer's
# browser test (view_browser.py) and its benchmark (bench/view_browser.py).
# WebGL runs on SwiftShader (the CPU), as on a machine without a GPU.
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
import fcntl
import json
import os
import select
import subprocess
import time


class Browser:
    """Chromium over --remote-debugging-pipe."""

    def __init__(self, chromium, profile, width, height):
        r_in, w_in = os.pipe()
        r_out, w_out = os.pipe()

        def fds():  # by way of copies above 9, whatever numbers the pipes got
            hi_in = fcntl.fcntl(r_in, fcntl.F_DUPFD, 10)
            hi_out = fcntl.fcntl(w_out, fcntl.F_DUPFD, 10)
            os.dup2(hi_in, 3)
            os.dup2(hi_out, 4)
        self.p = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--force-device-scale-factor=1",
             "--force-color-profile=srgb", "--hide-scrollbars", "--remote-debugging-pipe",
             "--window-size=%d,%d" % (width, height), "--user-data-dir=" + profile,
             "about:blank"],
            preexec_fn=fds, close_fds=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(r_in)
        os.close(w_out)
        self.w, self.r, self.buf, self.id, self.events = w_in, r_out, b"", 0, []
        t = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget",
                                 {"targetId": t, "flatten": True})["sessionId"]
        for m in ("Page.enable", "Runtime.enable"):
            self.call(m, session=True)
        self.call("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                  session=True)

    def read(self, limit=60):
        while b"\0" not in self.buf:
            ready, _, _ = select.select([self.r], [], [], limit)
            chunk = os.read(self.r, 1 << 20) if ready else b""
            if not chunk:
                raise RuntimeError("the browser stopped answering")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)

    def call(self, method, params=None, session=False):
        self.id += 1
        msg = {"id": self.id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = self.session
        os.write(self.w, json.dumps(msg).encode() + b"\0")
        while True:
            m = self.read()
            if m.get("id") == self.id:
                if "error" in m:
                    raise RuntimeError("%s: %s" % (method, m["error"]))
                return m.get("result", {})
            self.events.append(m)

    def js(self, expr):
        r = self.call("Runtime.evaluate", {"expression": expr, "awaitPromise": True,
                                           "returnByValue": True}, session=True)
        if "exceptionDetails" in r:
            raise RuntimeError("%s: %s" % (expr, r["exceptionDetails"]))
        return r["result"].get("value")

    def wait(self, expr, limit=120):
        t = time.time()
        while time.time() - t < limit:
            if self.js(expr):
                return True
            time.sleep(0.05)
        return False

    def errors(self):
        out = []
        for m in self.events:
            if m.get("method") == "Runtime.exceptionThrown":
                out.append(str(m["params"]["exceptionDetails"].get("text")))
            if m.get("method") == "Runtime.consoleAPICalled" and m["params"]["type"] == "error":
                out.append(" ".join(str(a.get("value")) for a in m["params"]["args"]))
        return out

    def close(self):
        try:
            self.call("Browser.close")
        except Exception:
            pass
        try:
            self.p.wait(20)
        except subprocess.TimeoutExpired:
            self.p.kill()
