#!/usr/bin/env python3
"""Drives the page in Debian's headless Chromium (SwiftShader WebGL2) through the DevTools protocol.

usage: tools/web_driver.py URL --screenshot OUT.png [--frames N] [--timeout S] [--eval JS]...
                           [--wait-console TEXT]... [--fetch FS_PATH_JS=LOCAL_FILE]...
                           [--reload [--wait-console-after-reload TEXT]...]

Opens URL, waits until the app has drawn N frames (Module.shadelabFrames, counted by the page's
main loop), runs each --eval expression and prints its value, waits until the console has a line
holding each --wait-console text, copies each --fetch file out of the page's file system (the JS
expression gives its path there), saves a screenshot of the page, and prints the page's console.
With --reload it then opens the page again in the same browser (its storage kept), waits for N
frames and each --wait-console-after-reload text. Exit 1 when the page stopped (abort, uncaught
error), never drew, or a console text never came.
Only the Python standard library: the protocol's WebSocket is spoken here.
"""
import argparse
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request


class WebSocket:
    """A client for one ws:// URL: text frames out (masked), whole messages in."""

    def __init__(self, url, timeout):
        assert url.startswith("ws://")
        hostport, _, path = url[5:].partition("/")
        host, _, port = hostport.partition(":")
        self.sock = socket.create_connection((host, int(port)), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall((f"GET /{path} HTTP/1.1\r\nHost: {hostport}\r\nUpgrade: websocket\r\n"
                           f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n").encode())
        reply = b""
        while b"\r\n\r\n" not in reply:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("the browser closed the connection during the handshake")
            reply += chunk
        head, _, self.buffer = reply.partition(b"\r\n\r\n")
        if b" 101 " not in head.split(b"\r\n")[0]:
            raise ConnectionError("the browser refused the WebSocket: " + head.split(b"\r\n")[0].decode())

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 20)
            if not chunk:
                raise ConnectionError("the browser closed the connection")
            self.buffer += chunk
        out, self.buffer = self.buffer[:n], self.buffer[n:]
        return out

    def send(self, text):
        payload = text.encode()
        header = bytearray([0x81])
        n = len(payload)
        if n < 126:
            header.append(0x80 | n)
        elif n < 1 << 16:
            header += bytes([0x80 | 126]) + struct.pack(">H", n)
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", n)
        mask = os.urandom(4)
        header += mask
        self.sock.sendall(bytes(header) + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def recv(self):
        message = b""
        while True:
            b0, b1 = self._read(2)
            n = b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._read(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._read(8))[0]
            payload = self._read(n)
            opcode = b0 & 0x0F
            if opcode == 0x8:
                raise ConnectionError("the browser closed the connection")
            if opcode in (0x9, 0xA):
                continue  # ping, pong
            message += payload
            if b0 & 0x80:
                return message.decode()


class Page:
    """One tab: commands by id, events kept for the console."""

    def __init__(self, ws):
        self.ws, self.next_id, self.console = ws, 0, []
        self.failed = None

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error'].get('message')}")
                return msg.get("result", {})
            self._event(msg)

    def _event(self, msg):
        method, params = msg.get("method"), msg.get("params", {})
        if method == "Runtime.consoleAPICalled":
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", []))
            self.console.append(f"{params.get('type')}: {text}")
        elif method == "Log.entryAdded":  # the browser's own messages (WebGL's errors among them)
            entry = params.get("entry", {})
            self.console.append(f"{entry.get('source')} {entry.get('level')}: {entry.get('text')}")
        elif method == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            text = details.get("exception", {}).get("description") or details.get("text", "")
            self.console.append("exception: " + text)
            self.failed = self.failed or text

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails'].get('text')}")
        return result.get("result", {}).get("value")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("url")
    parser.add_argument("--screenshot", required=True)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--size", default="1280,800")
    parser.add_argument("--eval", action="append", default=[])
    parser.add_argument("--wait-console", action="append", default=[])
    parser.add_argument("--fetch", action="append", default=[])
    parser.add_argument("--reload", action="store_true")
    parser.add_argument("--wait-console-after-reload", action="append", default=[])
    args = parser.parse_args()

    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        sys.exit("web_driver: no chromium on PATH (tools/install_deps.sh web installs Debian's)")
    port = free_port()
    profile = tempfile.mkdtemp(prefix="shadelab-chromium-")
    # As the probe that found these flags: SwiftShader's WebGL2, and no background traffic on a closed network.
    proc = subprocess.Popen([browser, "--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                             "--disable-background-networking", "--disable-component-update", "--disable-sync",
                             "--no-first-run", "--disable-quic", f"--user-data-dir={profile}",
                             f"--window-size={args.size}", f"--remote-debugging-port={port}", "about:blank"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    code = 1
    try:
        deadline = time.time() + args.timeout
        targets = None
        while time.time() < deadline and not targets:
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=2) as r:
                    targets = [t for t in json.load(r) if t.get("type") == "page"]
            except OSError:
                time.sleep(0.2)
        if not targets:
            sys.exit("web_driver: chromium did not start its DevTools endpoint")
        page = Page(WebSocket(targets[0]["webSocketDebuggerUrl"], timeout=args.timeout))
        page.call("Runtime.enable")
        page.call("Log.enable")
        page.call("Page.enable")
        w, h = (int(x) for x in args.size.split(","))
        page.call("Emulation.setDeviceMetricsOverride", width=w, height=h, deviceScaleFactor=1, mobile=False)
        start = time.time()
        page.call("Page.navigate", url=args.url)
        frames, first = 0, None
        while time.time() < deadline and not page.failed:
            frames = page.evaluate("(window.Module && Module.shadelabFrames) || 0") or 0
            if frames and first is None:
                first = time.time() - start
            if frames >= args.frames:
                break
            time.sleep(0.25)
        print(f"frames: {frames} in {time.time() - start:.1f} s; first frame after {first:.1f} s"
              if first is not None else f"frames: 0 in {time.time() - start:.1f} s")
        for expression in args.eval:
            print(f"eval {expression[:200]}: {json.dumps(page.evaluate(expression))}")
        missing = list(args.wait_console)
        while missing and time.time() < deadline and not page.failed:
            page.evaluate("0")  # lets the console events that arrived meanwhile in
            missing = [m for m in missing if not any(m in line for line in page.console)]
            time.sleep(0.25)
        for fetch in args.fetch:
            where, _, local = fetch.rpartition("=")
            try:
                data = page.evaluate("(() => { const a = Module.FS.readFile(" + where + "); let s = '';"
                                     " for (let i = 0; i < a.length; i += 0x8000)"
                                     " s += String.fromCharCode.apply(null, a.subarray(i, i + 0x8000));"
                                     " return btoa(s); })()")
            except RuntimeError as e:
                data = str(e)
            if not isinstance(data, str):
                missing.append(f"the file {where}")
                continue
            with open(local, "wb") as f:
                f.write(base64.b64decode(data))
            print(f"fetched {where} -> {local} ({os.path.getsize(local)} bytes)")
        if args.reload and not missing and not page.failed:
            print(f"reloading; console so far: {len(page.console)} lines")
            page.console.append("--- reloaded ---")
            mark = len(page.console)
            page.call("Page.reload", ignoreCache=False)
            time.sleep(1.0)
            frames = 0
            while time.time() < deadline and not page.failed and frames < args.frames:
                frames = page.evaluate("(window.Module && Module.shadelabFrames) || 0") or 0
                time.sleep(0.25)
            missing = list(args.wait_console_after_reload)
            while missing and time.time() < deadline and not page.failed:
                page.evaluate("0")
                missing = [m for m in missing if not any(m in line for line in page.console[mark:])]
                time.sleep(0.25)
        shot = page.call("Page.captureScreenshot", format="png")
        with open(args.screenshot, "wb") as f:
            f.write(base64.b64decode(shot["data"]))
        for line in page.console:
            print("console " + line)
        if page.failed:
            print(f"web_driver: the page failed: {page.failed}")
        elif frames < args.frames:
            print(f"web_driver: the page drew {frames} frames of {args.frames} in {args.timeout:.0f} s")
        elif missing:
            print(f"web_driver: never came: {'; '.join(missing)}")
        else:
            code = 0
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
        shutil.rmtree(profile, ignore_errors=True)
    sys.exit(code)


if __name__ == "__main__":
    main()
