#!/usr/bin/env python3
"""Browser test of `vascsim replay`: the page in real headless Chromium, driven through Selenium.

    python3 tests/browser/replay_browser_test.py --vascsim BUILD/apps/vascsim/vascsim \
        --run RUN_DIR --run-b RUN_DIR_B --probe BUILD/tests/mp4_probe --screenshots DIR

Starts `vascsim replay RUN_DIR --port 0` (later `vascsim replay RUN_DIR RUN_DIR_B`), reads the URL
from its one stdout line, and checks in the page: no JS errors; 403 without the token; scrubbing by
keys and by dragging the timeline; that toggling a layer shows exactly the server's frame for those
layers; the hover readout against /api/nodes; a deep link; bookmarks; the help overlay; an MP4
export checked with the probe (libavformat); compare mode with the tip distance against
/api/compare; with --run-c (another environment), the overlay's warning. Screenshots of each mode go to --screenshots. Prints `N passed, M failed` last and
exits non-zero on any failure.

For developing the page without the C++ server, `--url URL [--url-b URL_B]` uses servers already
running (a mock); then only the checks that need the executable (exit code) are skipped, and the
probe check runs only when --probe is given.
"""
import argparse
import base64
import fcntl
import json
import math
import os
import re
import select
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time
import traceback
import urllib.error
import urllib.parse
import urllib.request

try:
    import selenium  # noqa: F401
except ImportError:  # Debian's python3-selenium, when python3 is not the system interpreter
    sys.path.append('/usr/lib/python3/dist-packages')
from selenium import webdriver
from selenium.common.exceptions import TimeoutException, WebDriverException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import WebDriverWait

WAIT = 30          # s, the longest any single wait may take
URL_LINE = re.compile(r'^replay: (http://127\.0\.0\.1:(\d+)/\?token=([0-9A-Za-z_-]+))$')


class CheckFailed(Exception):
    pass


class Results:
    def __init__(self):
        self.passed = 0
        self.failed = 0
        self.skipped = 0

    def check(self, cond, what, detail=''):
        if cond:
            self.passed += 1
            print(f'PASS  {what}', flush=True)
        else:
            self.failed += 1
            print(f'FAIL  {what}' + (f': {detail}' if detail else ''), flush=True)
        return cond

    def skip(self, what, why):
        self.skipped += 1
        print(f'SKIP  {what}: {why}', flush=True)


R = Results()


def close(a, b, rel=1e-9):
    return a is not None and b is not None and abs(a - b) <= rel * max(1.0, abs(b))


# ---------------------------------------------------------------------------- HTTP
def http(url, data=None, method=None, headers=None):
    """(status, headers, body) of a request; HTTP errors are answers, not exceptions."""
    req = urllib.request.Request(url, data=data, method=method, headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=WAIT) as r:
            return r.status, dict(r.headers), r.read()
    except urllib.error.HTTPError as e:
        return e.code, dict(e.headers), e.read()


class Api:
    def __init__(self, url):
        u = urllib.parse.urlsplit(url)
        self.base = f'{u.scheme}://{u.netloc}'
        self.token = urllib.parse.parse_qs(u.query).get('token', [''])[0]
        self.page = url

    def url(self, path, **params):
        q = dict(params)
        if self.token:
            q['token'] = self.token
        return f'{self.base}{path}?{urllib.parse.urlencode(q, safe=",")}'

    def get(self, path, **params):
        status, _, body = http(self.url(path, **params))
        if status != 200:
            raise CheckFailed(f'GET {path} {params}: HTTP {status}: {body[:300]!r}')
        return json.loads(body)


# ---------------------------------------------------------------------------- the server
class Server:
    """`vascsim replay RUNS... --port 0`: reads the URL line, stops with SIGINT."""

    def __init__(self, exe, runs):
        self.cmd = [exe, 'replay', *runs, '--port', '0']
        print('starting:', ' '.join(self.cmd), flush=True)
        self.proc = subprocess.Popen(self.cmd, stdout=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True, bufsize=1)
        self.extra = []
        line = self._read_line(WAIT)
        m = URL_LINE.match(line.rstrip('\n'))
        if not m:
            self.proc.kill()
            raise CheckFailed(f'vascsim replay printed {line!r}, not "replay: http://127.0.0.1:PORT/?token=TOKEN"')
        self.url = m.group(1)
        self.drain = threading.Thread(target=self._drain, daemon=True)
        self.drain.start()

    def _read_line(self, timeout):
        end = time.time() + timeout
        while time.time() < end:
            if self.proc.poll() is not None:
                raise CheckFailed(f'vascsim replay exited with {self.proc.returncode} before printing its URL')
            r, _, _ = select.select([self.proc.stdout], [], [], 0.2)
            if r:
                return self.proc.stdout.readline()
        self.proc.kill()
        raise CheckFailed(f'vascsim replay printed no URL within {timeout} s')

    def _drain(self):
        for line in self.proc.stdout:
            self.extra.append(line)

    def stop(self, what, driver=None):
        # The page is closed first, as a user closes the tab: left open, it goes on asking the
        # stopped server (the series it refetches), and those refusals would land in the next
        # section's browser log.
        if driver:
            try:
                driver.get('about:blank')
            except WebDriverException:
                pass
        self.proc.send_signal(signal.SIGINT)
        try:
            code = self.proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            R.check(False, f'{what}: vascsim replay exits on SIGINT', 'still running 15 s after SIGINT (killed)')
            return
        self.drain.join(timeout=5)
        R.check(code == 0, f'{what}: vascsim replay exits 0 on SIGINT', f'exit code {code}')
        R.check(not self.extra, f'{what}: vascsim replay printed exactly one line on stdout',
                f'also printed {self.extra[:5]!r}')


# ---------------------------------------------------------------------------- the browser
def make_driver():
    opts = webdriver.ChromeOptions()
    if os.path.exists('/usr/bin/chromium'):
        opts.binary_location = '/usr/bin/chromium'
    for a in ('--headless=new', '--no-sandbox', '--disable-gpu', '--window-size=1600,1000',
              '--disable-dev-shm-usage', '--no-first-run', '--disable-extensions'):
        opts.add_argument(a)
    opts.set_capability('goog:loggingPrefs', {'browser': 'ALL'})
    driver = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=opts)
    driver.set_script_timeout(WAIT)
    driver.set_page_load_timeout(WAIT)
    return driver


class Page:
    def __init__(self, driver, api):
        self.d = driver
        self.api = api
        self.severe = []

    def js(self, script, *args):
        return self.d.execute_script(script, *args)

    def collect_log(self):
        try:
            for e in self.d.get_log('browser'):
                if e.get('level') == 'SEVERE':
                    self.severe.append(e.get('message', str(e)))
        except WebDriverException:
            pass

    def open(self, url):
        self.d.get(url)
        self.wait(lambda d: d.execute_script('return !!(window.vascsimReplay && window.vascsimReplay.state().range[1] >= 0 '
                                             '&& document.getElementById("time-readout").textContent)'),
                  'the page to start (window.vascsimReplay)')
        self.ready()

    def wait(self, cond, what, timeout=WAIT):
        try:
            return WebDriverWait(self.d, timeout, poll_frequency=0.05).until(cond)
        except TimeoutException:
            raise CheckFailed(f'timed out after {timeout} s waiting for {what}')

    def ready(self):
        """The shown image matches the wanted view, nothing in flight."""
        ok = self.d.execute_async_script(
            'const done = arguments[arguments.length - 1];'
            'window.vascsimReplay.ready().then(() => done(true), (e) => done(String(e)));')
        if ok is not True:
            raise CheckFailed(f'vascsimReplay.ready() failed: {ok}')

    def state(self):
        return self.js('return window.vascsimReplay.state()')

    def frame_url(self, run='a'):
        return self.js('return window.vascsimReplay.currentFrameUrl(arguments[0])', run)

    def frame_params(self, run='a'):
        u = self.frame_url(run)
        if not u:
            raise CheckFailed(f'no frame shown for run {run}')
        q = urllib.parse.parse_qs(urllib.parse.urlsplit(u).query, keep_blank_values=True)
        return {k: v[0] for k, v in q.items()}

    def frame_bytes(self, run='a'):
        b64 = self.d.execute_async_script(
            'const done = arguments[arguments.length - 1];'
            'window.vascsimReplay.currentFrameBase64(arguments[0]).then(done, (e) => done(null));', run)
        return base64.b64decode(b64) if b64 else None

    def view(self, run='a'):
        return self.js('return window.vascsimReplay.view(arguments[0])', run)

    def shown_time(self):
        text = self.d.find_element(By.ID, 'time-readout').text
        m = re.search(r'(-?\d+(?:\.\d+)?)\s*s', text)
        if not m:
            raise CheckFailed(f'#time-readout shows {text!r}, not a time in s')
        return float(m.group(1)), text

    def keys(self, *keys):
        self.js('if (document.activeElement && document.activeElement !== document.body) document.activeElement.blur();')
        ActionChains(self.d).send_keys(*keys).perform()

    def shot(self, directory, name):
        if directory:
            path = os.path.join(directory, name)
            self.d.save_screenshot(path)
            print(f'      screenshot {path}', flush=True)


def section(name, fn, *args):
    """Runs one group of checks; an exception is one failure, and the next group still runs."""
    print(f'--- {name}', flush=True)
    try:
        fn(*args)
    except CheckFailed as e:
        R.check(False, name, str(e))
    except Exception as e:  # a broken step must not hide the later checks
        R.check(False, name, f'{type(e).__name__}: {e}')
        traceback.print_exc()


# ---------------------------------------------------------------------------- checks
def check_load(page, shots):
    page.open(page.api.page)
    page.collect_log()
    R.check(not page.severe, 'the page loads without JS errors', '; '.join(page.severe[:5]))
    info = page.api.get('/api/run')
    st = page.state()
    R.check(st['layers'] == [l for l in info['layers'] if l in info['default_layers']],
            'the layer toggles start at the default layers', f"{st['layers']} vs {info['default_layers']}")
    checked = page.js('return Array.from(document.querySelectorAll("#layers input:checked")).map(c => c.value)')
    R.check(sorted(checked) == sorted(info['default_layers']), 'the checked layer boxes are the default layers', f'{checked}')
    greyed = page.js('return Array.from(document.querySelectorAll("#layers input:disabled")).map(c => c.value)')
    R.check(greyed == ['supports'], 'a maze run draws something for every layer but the supports (nothing holds its rod):'
            ' only that box is greyed out', f'{greyed}')
    img = page.js('const i = document.getElementById("frame-a"); return [i.naturalWidth, i.naturalHeight];')
    p = page.frame_params()
    R.check(img[0] == int(p['width']) and img[1] == int(p['height']) and int(p['width']) % 2 == 0 and int(p['height']) % 2 == 0,
            'the map shows a frame of the requested (even) size', f'image {img}, request {p.get("width")}x{p.get("height")}')
    rows = page.wait(lambda d: [th.text for th in d.find_elements(By.CSS_SELECTOR, '#summary tbody th')], 'the summary')
    R.check({'goal reached at', 'tip error RMS', 'tip error max', 'contact max', 'magnetic max'} <= set(rows)
            and not {'feed max', 'fed length'} & set(rows),
            'a steered run\'s summary has its navigation rows and no feed rows', repr(rows))
    page.shot(shots, 'single.png')


def check_token(api):
    status, _, _ = http(f'{api.base}/api/run')
    R.check(status == 403, '/api/run without the token gets 403', f'HTTP {status}')
    status, _, _ = http(f'{api.base}/api/run?token=0123456789abcdef0123456789abcdef')
    R.check(status == 403, '/api/run with a wrong token gets 403', f'HTTP {status}')
    status, _, _ = http(f'{api.base}/')
    R.check(status == 403, 'the page without the token gets 403', f'HTTP {status}')
    status, _, _ = http(api.url('/api/run'))
    R.check(status == 200, '/api/run with the token gets 200', f'HTTP {status}')


def expect_time(page, expected, what):
    try:
        WebDriverWait(page.d, WAIT, poll_frequency=0.05).until(lambda d: close(page.state()['t'], expected))
    except TimeoutException:
        pass
    t = page.state()['t']
    ok = R.check(close(t, expected), f'{what}: the time is {expected:.9g} s', f'state t = {t!r}')
    shown, text = page.shown_time()
    R.check(abs(shown - expected) <= 0.0005 + 1e-9, f'{what}: #time-readout shows {expected:.3f} s', f'shows {text!r}')
    page.ready()
    p = page.frame_params()
    R.check(close(float(p['t']), expected), f'{what}: the shown frame is requested at that time', f"frame t = {p['t']}")
    return ok


def check_keys(page):
    info = page.api.get('/api/run')
    first, last, dt = info['first_time'], info['last_time'], info['output_interval']
    page.keys(Keys.END)
    expect_time(page, last, 'End')
    page.keys(Keys.HOME)
    expect_time(page, first, 'Home')
    page.keys(Keys.ARROW_RIGHT)
    expect_time(page, min(last, first + dt), 'Right (one logged frame)')
    before = page.state()['t']
    ActionChains(page.d).key_down(Keys.SHIFT).send_keys(Keys.ARROW_RIGHT).key_up(Keys.SHIFT).perform()
    expect_time(page, min(last, before + 1.0), 'Shift+Right (1 s)')
    page.keys(Keys.ARROW_LEFT)
    t = page.state()['t']
    k = round((t - first) / dt)
    R.check(abs((t - first) / dt - k) < 1e-6 and t < min(last, before + 1.0),
            'Left steps back onto a logged frame', f't = {t}')


UNIT_FACTORS = {'N': 1.0, 'mN': 1e-3, 'µN': 1e-6, 'm': 1.0, 'mm': 1e-3, 'µm': 1e-6}


def seek_to_first_contact(page):
    """Moves the cursor to run a's first logged frame in wall contact (so a contact readout is
    not 0); returns the first frame's time, the output interval and that frame's index."""
    info = page.api.get('/api/run', run='a')
    first, dt = info['first_time'], info['output_interval']
    touches = [e['t'] for e in page.api.get('/api/events', run='a')['events'] if e['kind'] == 'contact_start']
    if not touches:
        raise CheckFailed('run a never touches a wall: no contact force to read out')
    start = round((touches[0] - first) / dt)
    page.js('window.vascsimReplay.setTime(arguments[0])', first + start * dt)
    page.wait(lambda d: close(page.state()['t'], first + start * dt, 1e-9), 'the first frame in contact')
    return first, dt, start


def plot_readout(page, label, t):
    """The values a plot's title row shows at time t, in SI: {run: value} ('a' when one run)."""
    want = f'{label} at {t:.3f} s: '
    text = page.wait(lambda d: d.execute_script(
        'for (const c of document.querySelectorAll("#plot-list canvas")) {'
        ' const l = c.getAttribute("aria-label") || ""; if (l.startsWith(arguments[0])) return l; }'
        ' return false;', want), f'the {label} plot to read out at {t:.3f} s')
    values = {}
    for part in text[len(want):].split(', '):
        m = re.fullmatch(r'(?:([AB]) )?(-?[\d.]+(?:e[-+]?\d+)?) (\S+)', part)
        if not m or m.group(3) not in UNIT_FACTORS:
            raise CheckFailed(f'the {label} plot reads {text!r}, not values with units')
        values[(m.group(1) or 'A').lower()] = float(m.group(2)) * UNIT_FACTORS[m.group(3)]
    return values, text


def check_plot_readouts(page, runs, what):
    """The plots' readouts at the cursor are the frame's values (as the map's HUD shows them),
    not the extremes of a pixel column's bucket, checked against node forces from /api/nodes at
    consecutive logged frames (a column holds several, so a bucket's extreme differs in some);
    a click on a plot seeks to the time under it."""
    first, dt, start = seek_to_first_contact(page)
    touching = 0
    for k in range(start, start + 6):
        if k > start:
            page.keys(Keys.ARROW_RIGHT)
        t = first + k * dt
        page.wait(lambda d: close(page.state()['t'], t, 1e-9), f'frame {k}')
        magnetic, magnetic_text = plot_readout(page, 'magnetic force', t)
        contact, contact_text = plot_readout(page, 'largest contact force', t)
        for r in runs:
            nodes = page.api.get('/api/nodes', t=repr(t), run=r)
            R.check(close(nodes['time'], t, 1e-9), f'{what}: run {r} has a frame at {t:.3f} s', f"{nodes['time']}")
            fx = sum(n['forces']['force/actuation'][0] for n in nodes['nodes'])
            fy = sum(n['forces']['force/actuation'][1] for n in nodes['nodes'])
            want_magnetic = math.hypot(fx, fy)
            want_contact = max(math.hypot(*n['forces']['force/contact']) for n in nodes['nodes'])
            touching += want_contact > 0
            # 4 significant digits are shown.
            R.check(r in magnetic and abs(magnetic[r] - want_magnetic) <= 5e-4 * want_magnetic + 1e-12,
                    f'{what}: run {r} magnetic force readout at {t:.3f} s is |sum of force/actuation| of the frame',
                    f'{magnetic_text!r} vs {want_magnetic:.6g} N')
            R.check(r in contact and abs(contact[r] - want_contact) <= 5e-4 * want_contact + 1e-12,
                    f'{what}: run {r} contact force readout at {t:.3f} s is the frame\'s largest node force/contact',
                    f'{contact_text!r} vs {want_contact:.6g} N')
    R.check(touching > 0, f'{what}: a frame read out has a wall contact force', f'from {first + start * dt} s')
    # A click on the middle of a plot seeks to the middle of the timeline.
    canvas = page.d.find_element(By.CSS_SELECTOR, '#plot-list canvas')
    area = page.js('const l = document.getElementById("plot-list").getBoundingClientRect(),'
                   ' t = document.getElementById("timeline-track").getBoundingClientRect(),'
                   ' c = arguments[0].getBoundingClientRect(); return [t.left - c.left, t.right - c.left, c.width, c.height];', canvas)
    x = round((area[0] + area[1]) / 2)
    ActionChains(page.d).move_to_element_with_offset(canvas, x - area[2] / 2, 0).click().perform()
    st = page.state()
    mid = 0.5 * (st['range'][0] + st['range'][1])
    R.check(abs(st['t'] - mid) <= 2 * (st['range'][1] - st['range'][0]) / (area[1] - area[0]),
            f'{what}: a click on a plot\'s middle seeks to the middle of the run', f"t = {st['t']}, middle {mid}")
    page.ready()


def check_added_plot(page):
    """A plot added below reads out its channel at the cursor (the norm of all contact forces,
    from /api/nodes), and its close button removes it."""
    from selenium.webdriver.support.ui import Select
    count = lambda: page.js('return document.querySelectorAll("#plot-list canvas").length')
    before = count()
    seek_to_first_contact(page)
    Select(page.d.find_element(By.ID, 'plot-channel')).select_by_value('force/contact')
    Select(page.d.find_element(By.ID, 'plot-reduce')).select_by_value('norm')
    page.d.find_element(By.ID, 'plot-add').click()
    page.wait(lambda d: count() == before + 1, 'the added plot')
    t = page.state()['t']
    nodes = page.api.get('/api/nodes', t=repr(t))
    want = math.sqrt(sum(f[0] ** 2 + f[1] ** 2 for f in (n['forces']['force/contact'] for n in nodes['nodes'])))
    values, text = plot_readout(page, 'force/contact (norm of all)', t)
    R.check(close(nodes['time'], t, 1e-9), 'added plot: the cursor is on a logged frame', f"{nodes['time']} vs {t}")
    R.check(want > 0 and abs(values['a'] - want) <= 5e-4 * want,
            'added plot: force/contact (norm of all) reads the norm of every node contact force of the frame',
            f'{text!r} vs {want:.6g} N')
    page.js('const p = [...document.querySelectorAll("#plot-list .plot")].pop(); p.querySelector(".plot-close").click();')
    page.wait(lambda d: count() == before, 'the added plot to be removed')


def check_drag(page):
    info = page.api.get('/api/run')
    first, last = info['first_time'], info['last_time']
    track = page.d.find_element(By.ID, 'timeline-track')
    w = track.size['width']
    ActionChains(page.d).move_to_element_with_offset(track, int(-w / 2 + 3), 0).click_and_hold() \
        .move_by_offset(int(w * 0.2), 0).move_by_offset(int(w * 0.2), 0) \
        .move_to_element_with_offset(track, 0, 0).release().perform()
    page.ready()
    t = page.state()['t']
    mid = first + 0.5 * (last - first)
    R.check(abs(t - mid) <= 0.1 * (last - first), 'dragging the timeline to its middle scrubs to mid-run',
            f't = {t:.3f}, middle {mid:.3f}')
    shown, text = page.shown_time()
    R.check(abs(shown - t) <= 0.0005 + 1e-9, 'after the drag #time-readout shows the time', f'{text!r} vs {t}')
    p = page.frame_params()
    R.check(close(float(p['t']), t, 1e-6), 'after the drag the frame shown is at the time', f"frame t = {p['t']}")


def check_layers(page, shots):
    info = page.api.get('/api/run')
    before = page.state()['layers']
    if 'trail' not in before:
        raise CheckFailed(f'trail is not among the shown layers {before}')
    box = page.d.find_element(By.ID, 'layer-trail')
    box.click()
    page.wait(lambda d: 'trail' not in page.state()['layers'], 'the trail layer to go off')
    page.ready()
    R.check(not box.is_selected(), 'the trail checkbox is unchecked')
    expected = [l for l in info['layers'] if l in before and l != 'trail']
    p = page.frame_params()
    layers = p.get('layers', None)
    R.check(layers is not None and 'trail' not in layers.split(','), "the frame URL's layers lack trail", f'layers={layers!r}')
    R.check(layers is not None and sorted(layers.split(',')) == sorted(expected),
            "the frame URL's layers are the defaults less trail", f'{layers!r} vs {expected}')
    shown = page.frame_bytes()
    direct = dict(p)
    direct.pop('token', None)
    direct['layers'] = ','.join(expected)
    status, headers, body = http(page.api.url('/api/frame.png', **direct))
    R.check(status == 200 and body[:8] == b'\x89PNG\r\n\x1a\n', 'the server answers /api/frame.png with a PNG', f'HTTP {status}')
    R.check(shown is not None and shown == body, 'the image shown equals the server frame for those layers',
            f'shown {len(shown or b"")} bytes, server {len(body)} bytes')
    view = {k.lower(): v for k, v in headers.items()}.get('x-vascsim-view')
    try:
        v = json.loads(view)
        R.check(all(k in v for k in ('time', 'scale', 'ox', 'oy')), 'the frame carries X-Vascsim-View', view)
    except (TypeError, ValueError):
        R.check(False, 'the frame carries X-Vascsim-View', f'{view!r}')
    with_trail = dict(direct, layers=','.join(l for l in info['layers'] if l in before))
    _, _, body_trail = http(page.api.url('/api/frame.png', **with_trail))
    R.check(body_trail != body, 'the frame with the trail differs from the one without (the layer matters)')
    page.shot(shots, 'layers.png')


def check_hover(page, shots):
    page.ready()
    view = page.view()
    if not view:
        raise CheckFailed('no X-Vascsim-View for the shown frame')
    nodes = page.api.get('/api/nodes', t=repr(view['time']))['nodes']
    rect = page.js('const r = document.getElementById("frame-a").getBoundingClientRect();'
                   'const i = document.getElementById("frame-a");'
                   'return {left: r.left, top: r.top, width: r.width, height: r.height, nw: i.naturalWidth, nh: i.naturalHeight};')
    box = page.d.find_element(By.ID, 'map-a')
    brect = page.js('const r = arguments[0].getBoundingClientRect(); return {left: r.left, top: r.top, width: r.width, height: r.height};', box)

    def client(n):
        px = view['ox'] + view['scale'] * n['position'][0]
        py = view['oy'] - view['scale'] * n['position'][1]
        return rect['left'] + px * rect['width'] / rect['nw'], rect['top'] + py * rect['height'] / rect['nh']

    tip = nodes[-1]
    cx, cy = client(tip)
    inside = brect['left'] + 2 < cx < brect['left'] + brect['width'] - 2 and brect['top'] + 2 < cy < brect['top'] + brect['height'] - 2
    if not inside:
        raise CheckFailed(f'the tip is drawn outside the map at ({cx:.1f}, {cy:.1f})')
    ox = int(round(cx - (brect['left'] + brect['width'] / 2)))
    oy = int(round(cy - (brect['top'] + brect['height'] / 2)))
    ActionChains(page.d).move_to_element_with_offset(box, ox, oy).perform()
    page.wait(lambda d: d.find_elements(By.ID, 'hover-node'), 'the hover readout to show a node')
    # Where the pointer really is (Selenium rounds from the element's centre): the node nearest to it.
    pointer = page.d.find_element(By.ID, 'hover-readout').get_attribute('data-pointer') or ''
    try:
        mx, my = (float(v) for v in pointer.split(','))
    except ValueError:
        raise CheckFailed(f'#hover-readout has no data-pointer ({pointer!r})')
    R.check(math.hypot(mx - cx, my - cy) <= 1.5, 'the pointer is on the tip', f'pointer ({mx}, {my}), tip ({cx:.2f}, {cy:.2f})')
    dists = [math.hypot(client(n)[0] - mx, client(n)[1] - my) for n in nodes]
    k = min(range(len(nodes)), key=lambda i: dists[i])
    want = nodes[k]
    idx = page.d.find_element(By.ID, 'hover-node').text.strip()
    R.check(idx == str(want['index']), 'hovering the tip shows its node index', f'readout node {idx}, nearest {want["index"]} (tip {tip["index"]})')
    x_text = page.d.find_element(By.ID, 'hover-x').text
    y_text = page.d.find_element(By.ID, 'hover-y').text

    def mm(text):
        m = re.search(r'-?\d+(?:\.\d+)?', text)
        return float(m.group(0)) if m else None
    x_mm, y_mm = mm(x_text), mm(y_text)
    R.check(x_mm is not None and abs(x_mm - want['position'][0] * 1e3) <= 0.0006,
            'the hover readout shows the node x in mm from /api/nodes', f'{x_text!r} vs {want["position"][0] * 1e3:.4f}')
    R.check(y_mm is not None and abs(y_mm - want['position'][1] * 1e3) <= 0.0006,
            'the hover readout shows the node y in mm from /api/nodes', f'{y_text!r} vs {want["position"][1] * 1e3:.4f}')
    speed = page.d.find_elements(By.ID, 'hover-speed')
    if 'speed' in want:
        s_mm = mm(speed[0].text) if speed else None
        R.check(s_mm is not None and abs(s_mm - want['speed'] * 1e3) <= 0.0006, 'the hover readout shows the node speed in mm/s',
                f'{speed[0].text if speed else None!r} vs {want["speed"] * 1e3:.4f}')
    rows = page.js('return Array.from(document.querySelectorAll("#hover-readout [data-force]")).map(r => r.dataset.force)')
    R.check(sorted(rows) == sorted(want.get('forces', {}).keys()), 'the hover readout lists every force at the node',
            f'{rows} vs {sorted(want.get("forces", {}).keys())}')
    page.shot(shots, 'hover.png')
    ActionChains(page.d).move_to_element(page.d.find_element(By.ID, 'sidebar')).perform()


def _client_of(page, view, world):
    """Client (CSS px) position of a world point on map A's shown image."""
    r = page.js('const i = document.getElementById("frame-a"); const r = i.getBoundingClientRect();'
                'return [r.left, r.top, r.width, r.height, i.naturalWidth, i.naturalHeight];')
    px = view['ox'] + view['scale'] * world[0]
    py = view['oy'] - view['scale'] * world[1]
    return r[0] + px * r[2] / r[4], r[1] + py * r[3] / r[5]


def _world_at(page, view, cx, cy):
    r = page.js('const i = document.getElementById("frame-a"); const r = i.getBoundingClientRect();'
                'return [r.left, r.top, r.width, r.height, i.naturalWidth, i.naturalHeight];')
    px = (cx - r[0]) * r[4] / r[2]
    py = (cy - r[1]) * r[5] / r[3]
    return (px - view['ox']) / view['scale'], (view['oy'] - py) / view['scale']


def check_zoom_pan(page):
    page.keys('f')
    page.wait(lambda d: page.state()['camera'] == 'fit' and page.state()['zoom'] == 1, 'F to fit')
    page.ready()
    box = page.d.find_element(By.ID, 'map-a')
    b = page.js('const r = arguments[0].getBoundingClientRect(); return [r.left, r.top, r.width, r.height];', box)
    ox, oy = int(-b[2] * 0.15), int(-b[3] * 0.1)
    cx, cy = b[0] + b[2] / 2 + ox, b[1] + b[3] / 2 + oy
    world = _world_at(page, page.view(), cx, cy)
    ActionChains(page.d).scroll_from_origin(ScrollOrigin.from_element(box, ox, oy), 0, -300).perform()
    page.wait(lambda d: page.state()['camera'] == 'center' and page.state()['zoom'] > 1.05, 'the wheel to zoom in')
    page.ready()
    st = page.state()
    after = _client_of(page, page.view(), world)
    R.check(math.hypot(after[0] - cx, after[1] - cy) <= 2.0, 'wheel zoom keeps the point under the cursor',
            f'zoom {st["zoom"]}, point moved from ({cx:.1f}, {cy:.1f}) to ({after[0]:.1f}, {after[1]:.1f})')
    p = page.frame_params()
    R.check(p.get('camera') == 'center' and 'center' in p and close(float(p['zoom']), st['zoom'], 1e-5),
            'the zoomed frame is requested with camera=center, center and zoom', f'{p}')
    # Drag the map: the point under the pointer follows it.
    start = (cx, cy)
    world = _world_at(page, page.view(), *start)
    ActionChains(page.d).move_to_element_with_offset(box, ox, oy).click_and_hold().move_by_offset(40, 20) \
        .move_by_offset(60, 30).release().perform()
    page.ready()
    after = _client_of(page, page.view(), world)
    R.check(math.hypot(after[0] - (cx + 100), after[1] - (cy + 50)) <= 2.0, 'dragging the map pans with the pointer',
            f'point at ({after[0]:.1f}, {after[1]:.1f}), pointer at ({cx + 100:.1f}, {cy + 50:.1f})')
    z = page.state()['zoom']
    page.keys('+')
    page.wait(lambda d: page.state()['zoom'] > z * 1.01, '+ to zoom in')
    R.check(page.state()['camera'] == 'center', '+ zooms about the map centre (camera stays)', f'{page.state()}')
    page.keys('t')
    page.wait(lambda d: page.state()['camera'] == 'follow', 'T to follow the tip')
    page.ready()
    R.check(page.frame_params().get('camera') == 'follow', 'T requests camera=follow', f'{page.frame_params()}')
    page.keys('f')
    page.wait(lambda d: page.state()['camera'] == 'fit' and page.state()['zoom'] == 1, 'F to fit')
    page.ready()
    R.check(page.frame_params().get('camera') == 'fit' and float(page.frame_params().get('zoom')) == 1, 'F requests camera=fit, zoom=1')


def check_playback(page):
    page.keys(Keys.HOME)
    page.wait(lambda d: close(page.state()['t'], page.state()['range'][0]), 'Home')
    from selenium.webdriver.support.ui import Select
    Select(page.d.find_element(By.ID, 'speed-select')).select_by_value('4')
    page.wait(lambda d: page.state()['speed'] == 4, 'the speed to be 4x')
    t0, w0 = page.js('return [window.vascsimReplay.state().t, performance.now()]')
    page.keys(Keys.SPACE)
    page.wait(lambda d: page.state()['playing'], 'Space to start playback')
    page.wait(lambda d: page.state()['t'] >= t0 + 2.0 or not page.state()['playing'], 'playback to advance 2 s')
    page.keys(Keys.SPACE)
    page.wait(lambda d: not page.state()['playing'], 'Space to pause')
    t1, w1 = page.js('return [window.vascsimReplay.state().t, performance.now()]')
    rate = (t1 - t0) / max(1e-3, (w1 - w0) / 1000)
    R.check(t1 > t0 and 2.0 <= rate <= 4.4, 'playback at 4x advances about 4 simulated s per second', f'{rate:.2f} s/s')
    page.ready()
    p = page.frame_params()
    R.check(close(float(p['t']), page.state()['t']), 'after pausing the frame shown is at the time', f"{p['t']} vs {page.state()['t']}")
    Select(page.d.find_element(By.ID, 'speed-select')).select_by_value('1')


def check_deeplink(page, shots):
    info = page.api.get('/api/run')
    expected_t = min(max(10.0, info['first_time']), info['last_time'])
    page.d.get('about:blank')
    page.open(page.api.page + '#t=10&zoom=2&camera=follow&layers=walls,rod')
    st = page.state()
    R.check(close(st['t'], expected_t), 'the deep link sets the time', f"t = {st['t']}")
    shown, text = page.shown_time()
    R.check(abs(shown - expected_t) <= 0.0005, f'the deep link shows {expected_t:.3f} s', f'{text!r}')
    zoom = page.d.find_element(By.ID, 'zoom-input').get_attribute('value')
    R.check(zoom is not None and close(float(zoom), 2.0), 'the zoom control shows 2', f'{zoom!r}')
    cam = page.d.find_element(By.ID, 'camera-select').get_attribute('value')
    R.check(cam == 'follow', 'the camera control shows follow', f'{cam!r}')
    checked = page.js('return Array.from(document.querySelectorAll("#layers input:checked")).map(c => c.value)')
    R.check(sorted(checked) == ['rod', 'walls'], 'the layer boxes show walls and rod only', f'{checked}')
    p = page.frame_params()
    R.check(close(float(p.get('t', 'nan')), expected_t) and close(float(p.get('zoom', 'nan')), 2.0)
            and p.get('camera') == 'follow' and p.get('layers') == 'walls,rod',
            'the frame is requested with the link\'s view', f'{p}')
    page.shot(shots, 'deeplink.png')
    # A changed fragment (a pasted link, the back button) is applied too.
    t2 = min(max(5.0, info['first_time']), info['last_time'])
    page.js('location.hash = arguments[0]', f't={t2}&zoom=1&camera=fit&layers={",".join(info["default_layers"])}')
    page.wait(lambda d: close(page.state()['t'], t2) and page.state()['camera'] == 'fit', 'the new fragment to apply')
    page.ready()
    st = page.state()
    R.check(close(st['zoom'], 1.0) and sorted(st['layers']) == sorted(info['default_layers']),
            'a changed fragment is applied', f'{st}')
    # The page keeps its fragment up to date: it reopens the exact view.
    page.keys(Keys.ARROW_RIGHT)
    try:
        WebDriverWait(page.d, 5, poll_frequency=0.05).until(lambda d: close(_hash_t(d), page.state()['t'], 1e-8))
    except TimeoutException:
        pass
    R.check(close(_hash_t(page.d), page.state()['t'], 1e-8), 'the URL fragment holds the current time',
            page.js('return location.hash'))


def _hash_t(d):
    h = d.execute_script('return location.hash')
    m = re.search(r'[#&]t=([-0-9.eE+]+)', h or '')
    return float(m.group(1)) if m else None


def check_bookmark(page):
    name = f'browser test {int(time.time() * 1000) % 100000}'
    page.keys('b')
    page.wait(lambda d: d.find_element(By.ID, 'bookmark-dialog').is_displayed(), 'the bookmark dialog')
    field = page.d.find_element(By.ID, 'bookmark-name')
    page.wait(lambda d: d.switch_to.active_element == field, 'the name field to have focus', timeout=5)
    t = page.state()['t']
    field.send_keys(name)
    field.send_keys(Keys.ENTER)
    page.wait(lambda d: not d.find_element(By.ID, 'bookmark-dialog').is_displayed(), 'the dialog to close')
    page.wait(lambda d: name in d.find_element(By.ID, 'bookmark-list').text, 'the bookmark in the list')
    R.check(True, 'the bookmark appears in the list')
    marks = page.api.get('/api/bookmarks')['bookmarks']
    mine = [b for b in marks if b.get('name') == name]
    R.check(len(mine) == 1 and close(float(mine[0]['t']), t, 1e-6) and 't=' in mine[0].get('view', ''),
            'GET /api/bookmarks has it with its time and view', f'{mine}')
    # Clicking it brings its view back.
    page.keys(Keys.HOME)
    page.wait(lambda d: not close(page.state()['t'], t) or close(t, page.state()['range'][0]), 'Home')
    items = [li for li in page.d.find_elements(By.CSS_SELECTOR, '#bookmark-list li') if li.get_attribute('data-name') == name]
    if items:
        items[0].click()
        page.wait(lambda d: close(page.state()['t'], t, 1e-6), 'the bookmark to apply', timeout=10)
    R.check(bool(items) and close(page.state()['t'], t, 1e-6), 'clicking the bookmark returns to its time', f"t = {page.state()['t']}")


def check_help(page, shots):
    page.keys('?')
    page.wait(lambda d: d.find_element(By.ID, 'help-overlay').is_displayed(), 'the help overlay')
    R.check(True, '? shows the shortcut help')
    page.shot(shots, 'help.png')
    page.keys(Keys.ESCAPE)
    page.wait(lambda d: not d.find_element(By.ID, 'help-overlay').is_displayed(), 'Escape to close the help')
    R.check(True, 'Escape closes the help')


def check_export(page, shots, probe, workdir):
    info = page.api.get('/api/run')
    t0 = info['first_time']
    t1 = min(info['last_time'], t0 + 1.0)
    for fid, value in (('export-from', t0), ('export-to', t1)):
        el = page.d.find_element(By.ID, fid)
        el.clear()
        el.send_keys(repr(value))
    page.js('document.activeElement.blur()')
    size = page.state()['size']
    page.d.find_element(By.ID, 'export-start').click()
    page.wait(lambda d: d.find_element(By.ID, 'export-progress').is_displayed(), 'the export progress bar')
    R.check(True, 'the export shows its progress')
    page.wait(lambda d: d.find_element(By.ID, 'export-download').is_displayed()
              or 'failed' in d.find_element(By.ID, 'export-status').text, 'the export to finish')
    link = page.d.find_element(By.ID, 'export-download')
    R.check(link.is_displayed(), 'the export finishes and offers a download', page.d.find_element(By.ID, 'export-status').text)
    href = link.get_attribute('href') or ''
    m = re.search(r'/api/export/file\?(?:.*&)?id=(\d+)', href)
    if not m:
        raise CheckFailed(f'the download link {href!r} is not /api/export/file?id=N')
    eid = m.group(1)
    st = page.api.get('/api/export/status', id=eid)
    R.check(st.get('state') == 'done' and st.get('frames_done') == st.get('frames_total'), 'the export status is done', f'{st}')
    status, _, body = http(page.api.url('/api/export/file', id=eid))
    R.check(status == 200 and len(body) > 0, 'the exported MP4 downloads', f'HTTP {status}, {len(body)} bytes')
    page.shot(shots, 'export.png')
    if not probe:
        R.skip('the MP4 is H.264 of the view size', 'no --probe given')
        return
    path = os.path.join(workdir, 'export.mp4')
    with open(path, 'wb') as f:
        f.write(body)
    out = subprocess.run([probe, path], capture_output=True, text=True, timeout=WAIT)
    try:
        meta = json.loads(out.stdout)
    except ValueError:
        raise CheckFailed(f'{probe} printed {out.stdout!r} (stderr {out.stderr!r}, exit {out.returncode})')
    R.check(meta.get('codec') == 'h264', 'the exported video is H.264', f'{meta}')
    R.check((meta.get('frames') or 0) > 0, 'the exported video has frames', f'{meta}')
    R.check(meta.get('frames') == st.get('frames_total'), 'the exported video has the frames the status counted',
            f"{meta.get('frames')} vs {st.get('frames_total')}")
    R.check([meta.get('width'), meta.get('height')] == size, 'the exported video has the view size', f'{meta} vs view {size}')


def check_compare(page, shots):
    page.open(page.api.page)
    page.collect_log()
    R.check(not page.severe, 'compare: the page loads without JS errors', '; '.join(page.severe[:5]))
    a, b = page.api.get('/api/run', run='a'), page.api.get('/api/run', run='b')
    R.check('b' in a.get('runs', []), "compare: /api/run lists run b", f"{a.get('runs')}")
    st = page.state()
    want = [min(a['first_time'], b['first_time']), max(a['last_time'], b['last_time'])]
    R.check(close(st['range'][0], want[0]) and close(st['range'][1], want[1]),
            'compare: the timeline covers both runs', f"{st['range']} vs {want}")
    shown = page.js('return ["frame-a", "frame-b"].map(id => { const i = document.getElementById(id); const r = i.getBoundingClientRect();'
                    ' return [i.naturalWidth, r.width, r.left]; })')
    R.check(all(s[0] > 0 and s[1] > 0 for s in shown) and shown[1][2] > shown[0][2] + shown[0][1] * 0.5,
            'compare: both maps are shown side by side', f'{shown}')
    pa, pb = page.frame_params('a'), page.frame_params('b')
    R.check(pb.get('run') == 'b' and all(pa.get(k) == pb.get(k) for k in ('t', 'width', 'height', 'camera', 'zoom', 'layers')),
            "compare: map B is run b's frame with the same view", f'{pa} / {pb}')

    def distance_matches(what):
        t = page.state()['t']
        page.wait(lambda d: d.find_element(By.ID, 'tip-distance').get_attribute('data-t') is not None and
                  close(float(d.find_element(By.ID, 'tip-distance').get_attribute('data-t')), t, 1e-8),
                  'the tip distance at the current time')
        text = page.d.find_element(By.ID, 'tip-distance').text
        m = re.search(r'(-?\d+(?:\.\d+)?)\s*mm', text)
        c = page.api.get('/api/compare', t=repr(t))
        R.check(m is not None and abs(float(m.group(1)) / 1e3 - c['tip_distance']) <= 1e-6,
                f'compare: the tip distance {what} equals /api/compare', f'{text!r} vs {c["tip_distance"]} m')
    distance_matches('at the start')
    page.keys(Keys.END)
    page.wait(lambda d: close(page.state()['t'], want[1]), 'End')
    page.ready()
    distance_matches('at the end')
    ActionChains(page.d).key_down(Keys.SHIFT).send_keys(Keys.ARROW_LEFT).key_up(Keys.SHIFT).perform()
    page.ready()
    distance_matches('1 s before the end')
    page.shot(shots, 'compare.png')
    check_plot_readouts(page, ['a', 'b'], 'compare')
    # Overlay: one map, run a's frame with run b's rod.
    from selenium.webdriver.support.ui import Select
    Select(page.d.find_element(By.ID, 'compare-mode')).select_by_value('overlay')
    page.wait(lambda d: not d.find_element(By.ID, 'map-b').is_displayed(), 'map B to hide in overlay mode')
    page.ready()
    p = page.frame_params('a')
    R.check(p.get('overlay') == 'b', 'compare: the overlay toggle requests overlay=b', f'{p}')
    clip = page.d.find_element(By.ID, 'command-clip').get_attribute('value')
    R.check(f" --overlay {page.api.get('/api/run', run='b')['path']}" in clip,
            'compare: "copy as command" draws run b over run a too (--overlay B)', clip)
    label = page.d.find_element(By.ID, 'map-label-a').text
    R.check("B's rod" in label and 'another environment' not in label,
            'compare: the overlay of a run in the same maze carries no environment warning', label)
    page.shot(shots, 'compare_overlay.png')
    page.collect_log()


def check_other_environment(page, shots):
    """Run b from another environment overlaid on run a's map: the map's label says so."""
    page.open(page.api.page)
    R.check(page.api.get('/api/run', run='b').get('same_environment_as_a') is False,
            'other environment: /api/run says run b ran elsewhere', '')
    from selenium.webdriver.support.ui import Select
    Select(page.d.find_element(By.ID, 'compare-mode')).select_by_value('overlay')
    page.ready()
    page.wait(lambda d: 'B ran in another environment' in d.find_element(By.ID, 'map-label-a').text,
              "the map label's warning that B ran in another environment")
    Select(page.d.find_element(By.ID, 'compare-mode')).select_by_value('side')
    page.wait(lambda d: 'another environment' not in d.find_element(By.ID, 'map-label-a').text,
              'the warning to go in the side-by-side view, where each run has its own map')
    Select(page.d.find_element(By.ID, 'compare-mode')).select_by_value('overlay')
    page.ready()
    page.shot(shots, 'compare_overlay_other_environment.png')
    page.collect_log()



def log_layout(path):
    """(data offset, record bytes) of a frame log (docs/frame-log.md)."""
    with open(path, 'rb') as f:
        head = f.read(1 << 22)
    if head[:8] != b'VSIMLOG\0':
        raise CheckFailed(f'{path}: not a frame log')
    _, _, channels = struct.unpack_from('<III', head, 8)
    at, doubles = 20, 1
    for _ in range(channels):
        for _ in range(2):  # name, unit
            (n,) = struct.unpack_from('<I', head, at)
            at += 4 + n
        at += 1  # layout
        (count,) = struct.unpack_from('<I', head, at)
        at += 4
        doubles += count
    (n,) = struct.unpack_from('<I', head, at)
    at += 4 + n
    return (at + 7) // 8 * 8, 8 * doubles


def start_long_run(exe, workdir, name, **sections):
    """`vascsim run` of a scene that outlasts the test (fixed 10 us steps on a free rod, a frame
    every 10 ms: tests/cli_test_support.h's kLongRunScene, with SECTIONS added) into
    WORKDIR/NAME, once its log exists."""
    scene = os.path.join(workdir, name + '.json')
    with open(scene, 'w') as f:
        json.dump({'maze': None, 'rod': {'nodes': 40}, 'solver': {'dt': 1e-5},
                   'run': {'duration': 1000, 'output_interval': 0.01}, **sections}, f)
    run = os.path.join(workdir, name)
    proc = subprocess.Popen([exe, 'run', scene, '--out', run, '--quiet'], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.time() + 30
    while time.time() < deadline and not os.path.exists(os.path.join(run, 'frames.vlog')):
        time.sleep(0.05)
    return run, proc


def check_stopped_run(driver, exe, shots, workdir):
    """A run stopped by Ctrl-C reads as stopped, not failed: the summary's result, the note under
    it (which goes to the last frame) and the timeline's mark say so."""
    # Gravity of zero logs force/external, flat zero: the plot checked below.
    # Clamped at its root and on a roller at its tip: the supports layer draws both.
    run, proc = start_long_run(exe, workdir, 'stopped', loads={'gravity': {'enabled': True, 'acceleration': [0, 0]}},
                               boundary={'clamp': 'first_edge', 'supports': [{'node': -1, 'hold': 'y'}]})
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    R.check(proc.returncode == -signal.SIGINT and os.path.exists(os.path.join(run, 'summary.json')),
            'stopped run: Ctrl-C ends the run by SIGINT after writing its summary', f'exit {proc.returncode}: {err[-300:]!r}')
    server = Server(exe, [run])
    try:
        page = Page(driver, Api(server.url))
        page.open(page.api.page)
        result = page.wait(lambda d: d.find_elements(By.CSS_SELECTOR, '#summary td[data-key="result"]'), 'the summary')
        R.check(result[0].text == 'stopped', 'stopped run: the summary\'s result reads "stopped"', repr(result[0].text))
        rows = [th.text for th in page.d.find_elements(By.CSS_SELECTOR, '#summary tbody th')]
        R.check('simulated' in rows and not {'goal reached at', 'tip error RMS', 'contact max', 'magnetic max'} & set(rows),
                'stopped run: a free rod\'s summary has no navigation rows (they were all "–")', repr(rows))
        notes = page.d.find_elements(By.CSS_SELECTOR, '#summary .failure-note')
        R.check(len(notes) == 1 and notes[0].text.startswith('stopped by SIGINT (Ctrl-C) at t = '),
                'stopped run: the note under the summary says who stopped it', repr([n.text for n in notes]))
        marks = page.d.find_elements(By.CSS_SELECTOR, '.event-mark.failure')
        R.check(len(marks) == 1 and marks[0].get_attribute('title').startswith('run stopped by SIGINT (Ctrl-C) at t = '),
                'stopped run: the timeline marks where it was stopped', repr([m.get_attribute('title') for m in marks]))
        # A force that is zero throughout is plotted on an axis of a readable unit range (a flat
        # zero read "0.000001" beside the zero).
        from selenium.webdriver.support.ui import Select
        Select(page.d.find_element(By.ID, 'plot-channel')).select_by_value('force/external')
        Select(page.d.find_element(By.ID, 'plot-reduce')).select_by_value('max')
        page.d.find_element(By.ID, 'plot-add').click()
        ticks = page.wait(lambda d: d.execute_script(
            'for (const c of document.querySelectorAll("#plot-list canvas"))'
            ' if ((c.getAttribute("aria-label") || "").startsWith("force/external") && c.dataset.yTicks) return c.dataset.yTicks;'
            ' return false;'), 'the force/external plot to draw its axis').split()
        R.check(len(ticks) >= 2 and float(ticks[-1]) >= 0.5 and all(len(t.partition('.')[2]) <= 1 for t in ticks),
                'stopped run: a flat zero is plotted on an axis of one display unit', repr(ticks))
        supports = page.js('const c = document.getElementById("layer-supports"); return [c.disabled, c.checked];')
        R.check(supports == [False, True], 'stopped run: the supports layer of a clamped rod is on and not greyed out',
                repr(supports))
        page.shot(shots, 'stopped.png')
        page.collect_log()
        R.check(not page.severe, 'no JS errors in the browser log (stopped run)', '; '.join(page.severe[:5]))
    finally:
        server.stop('stopped run', driver)


def check_killed_run(driver, exe, shots, workdir):
    """A run killed with kill -9 while watched live: the live badge goes, the summary panel says
    it was killed, and the map at the cursor is drawn again with the HUD's "Run killed" row,
    though the cursor did not move."""
    run, proc = start_long_run(exe, workdir, 'killed')
    server = Server(exe, [run])
    try:
        page = Page(driver, Api(server.url))
        page.open(page.api.page)
        page.wait(lambda d: d.find_element(By.ID, 'live-badge').is_displayed(), 'the live badge')
        page.keys(Keys.END)
        # Frozen first, so that the page has every frame the run wrote before the kill: then the
        # kill changes nothing but how the run ended (new frames would move the cursor anyway).
        proc.send_signal(signal.SIGSTOP)
        time.sleep(0.2)
        last = page.api.get('/api/run')['last_time']
        page.wait(lambda d: page.state()['range'][1] == last and page.state()['t'] == last,
                  "the cursor to follow to the frozen run's last frame")
        page.ready()
        before = page.frame_bytes()
        proc.kill()
        proc.wait(timeout=30)
        page.wait(lambda d: not d.find_element(By.ID, 'live-badge').is_displayed(), 'the live badge to go')
        R.check(True, 'killed run: the live badge goes when the run is killed')
        text = page.wait(lambda d: 'killed' in d.find_element(By.ID, 'summary').text and d.find_element(By.ID, 'summary').text,
                         'the summary panel to say the run was killed')
        R.check(text.startswith('no summary.json: the run was killed before its end'), 'killed run: the summary panel says so', repr(text))
        page.ready()
        shown = page.frame_bytes()
        params = page.frame_params()
        params.pop('token', None)
        status, _, body = http(page.api.url('/api/frame.png', **params))
        R.check(status == 200 and shown == body, 'killed run: the map shown is the server\'s frame of the killed run',
                f'HTTP {status}, shown {len(shown or b"")} bytes, server {len(body)} bytes')
        R.check(shown != before and abs(float(params['t']) - last) < 1e-6,
                'killed run: the map at the same time was drawn again (its HUD now says "Run killed")')
        # Its short range has labels of three digits: the first ("0.00") lost its first digit
        # past the ruler's left edge. The rows below the bar and its ticks are the labels'.
        edges = page.d.execute_script(
            'const c = document.getElementById("timeline-ruler"), g = c.getContext("2d"), dpr = window.devicePixelRatio || 1;'
            ' const y = Math.round((document.getElementById("timeline-played").offsetTop + 11) * dpr), rows = c.height - y;'
            ' const ink = x => Array.from(g.getImageData(x, y, 1, rows).data).filter((v, i) => i % 4 === 3 && v > 0).length;'
            ' return [ink(0), ink(c.width - 1)];')
        R.check(edges == [0, 0], "killed run: the timeline's end labels are whole (no ink at the ruler's edges)", repr(edges))
        page.shot(shots, 'killed.png')
        page.collect_log()
        R.check(not page.severe, 'no JS errors in the browser log (killed run)', '; '.join(page.severe[:5]))
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        server.stop('killed run', driver)


# A feed into a dead end that squashes the rod: a run with warnings.
CRAMMED_SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', 'crammed_feed.json')


def check_warnings(driver, exe, shots, workdir):
    """A run's warnings are listed under its summary in the words `vascsim run` printed, marked
    on the timeline, and a click on one goes to where it first happened."""
    run = os.path.join(workdir, 'crammed')
    done = subprocess.run([exe, 'run', CRAMMED_SCENE, '--out', run, '--quiet'], capture_output=True, text=True, timeout=300)
    printed = re.findall(r'^vascsim run: warning: (.*) \(summary\.json /warnings\)$', done.stderr, re.M)
    R.check(done.returncode == 1 and len(printed) >= 2, 'warnings: the crammed run fails after printing warnings',
            f'exit {done.returncode}: {done.stderr[-400:]!r}')
    with open(os.path.join(run, 'summary.json')) as f:
        summary = json.load(f)['warnings']
    server = Server(exe, [run])
    try:
        page = Page(driver, Api(server.url))
        page.open(page.api.page)
        notes = page.wait(lambda d: d.find_elements(By.CSS_SELECTOR, '#run-warnings .warning-note'), 'the warnings')
        texts = [n.text for n in notes]
        R.check(sorted(texts) == sorted('warning: ' + p for p in printed),
                'warnings: the summary panel lists the warnings vascsim run printed', f'{texts} vs {printed}')
        marks = page.d.find_elements(By.CSS_SELECTOR, '.event-mark.warning')
        R.check(len(marks) == len(printed), 'warnings: each is marked on the timeline', f'{len(marks)} marks')
        # The rod is only pushed from its root (control.mode "none"): the page shows the drive's
        # push, not a tip error or magnetic force nothing made (a flat zero and a distance to a
        # target the tip did not follow).
        labels = page.wait(lambda d: d.execute_script(
            'const l = [...document.querySelectorAll("#plot-list canvas")].map((c) => c.getAttribute("aria-label") || "");'
            ' return l.some((x) => x.startsWith("feed force")) && l;'), 'the feed force plot')
        R.check(not any(l.startswith(('tip error', 'magnetic force')) for l in labels),
                'warnings: a rod only pushed from its root has a feed force plot and no tip error or magnetic plot',
                repr(labels))
        # Its layer boxes: the magnetic arrows draw nothing for it, so that box is greyed out and
        # says why; the walls and contact arrows do.
        boxes = page.js('return Object.fromEntries(Array.from(document.querySelectorAll("#layers input")).map('
                        '(c) => [c.value, [c.disabled, c.parentElement.title]]))')
        R.check(boxes.get('magnetic') == [True, 'This run does not record a magnetic force']
                and not boxes.get('walls', [True])[0] and not boxes.get('contact', [True])[0],
                'warnings: the magnetic layer box of a run only pushed from its root is greyed out and says why',
                repr(boxes))
        rows = [th.text for th in page.d.find_elements(By.CSS_SELECTOR, '#summary tbody th')]
        R.check({'feed max', 'fed length'} <= set(rows) and not {'tip error RMS', 'magnetic max'} & set(rows),
                'warnings: its summary gives the feed\'s push and length, no tip error or magnetic maximum', repr(rows))
        # Forces of a newton or more read in N, as the HUD gives them, and smaller ones in mN.
        with open(os.path.join(run, 'summary.json')) as f:
            nav = json.load(f)['navigation']
        for key, value in (('contact max', nav['contact_force_max']), ('feed max', nav['advance']['feed_force_max'])):
            cell = page.d.find_element(By.CSS_SELECTOR, f'#summary td[data-key="{key}"]').text
            m = re.fullmatch(r'(-?[\d.]+) (N|mN)', cell)
            R.check(m is not None and m.group(2) == ('N' if abs(value) >= 1 else 'mN')
                    and abs(float(m.group(1)) * UNIT_FACTORS[m.group(2)] - value) <= 1e-3 * abs(value),
                    f'warnings: the summary gives {key} in a unit that suits it', f'{cell!r} for {value} N')
        # The squashed rod's note goes to the first frame it was squashed in (summary.json).
        squashed = [n for n in notes if 'stretched or squashed' in n.text]
        want = summary['large_axial_strain']['first_time']
        if R.check(len(squashed) == 1, 'warnings: the large strain is listed', f'{texts}'):
            page.keys(Keys.END)
            squashed[0].click()
            page.wait(lambda d: close(page.state()['t'], want, 1e-9), f'the time to go to {want} s')
            page.ready()
            R.check(close(float(page.frame_params()['t']), want, 1e-9),
                    'warnings: a click on a warning shows the frame where it first happened', f"{page.frame_params()['t']}")
            # The keyboard reaches the note too: focused (as Tab would), Enter goes there.
            page.keys(Keys.END)
            page.wait(lambda d: not close(page.state()['t'], want, 1e-9), 'the time to leave the warning')
            focused = page.js('arguments[0].focus(); return document.activeElement === arguments[0];', squashed[0])
            R.check(focused, 'warnings: a warning takes the keyboard focus')
            ActionChains(page.d).send_keys(Keys.ENTER).perform()
            page.wait(lambda d: close(page.state()['t'], want, 1e-9), f'Enter to go to {want} s')
            page.ready()
            R.check(close(float(page.frame_params()['t']), want, 1e-9),
                    'warnings: Enter on a focused warning shows the frame where it first happened', f"{page.frame_params()['t']}")
        # The run's failure, listed under the summary, goes to the last frame before it.
        failure = page.d.find_elements(By.CSS_SELECTOR, '#summary .failure-note')
        last = page.api.get('/api/run')['last_time']
        if R.check(len(failure) == 1, 'warnings: the failure is listed under the summary', f'{len(failure)} notes'):
            page.keys(Keys.HOME)
            page.wait(lambda d: not close(page.state()['t'], last, 1e-9), 'the time to leave the last frame')
            failure[0].click()
            page.wait(lambda d: close(page.state()['t'], last, 1e-9), f'the time to go to {last} s')
            page.ready()
            R.check(close(float(page.frame_params()['t']), last, 1e-9),
                    'warnings: a click on the failure shows the last frame before it', f"{page.frame_params()['t']}")
        page.shot(shots, 'warnings.png')
        page.collect_log()
        R.check(not page.severe, 'no JS errors in the browser log (warnings)', '; '.join(page.severe[:5]))
    finally:
        server.stop('warnings', driver)


def hold_run_claim(run_dir):
    """The claim `vascsim run` holds on the directory it writes (sim/io/output_file.h): an open file
    description lock on DIR/.vascsim-run.lock, held while the returned descriptor stays open."""
    fd = os.open(os.path.join(run_dir, '.vascsim-run.lock'), os.O_RDWR | os.O_CREAT, 0o644)
    fcntl.fcntl(fd, fcntl.F_OFD_SETLK, struct.pack('hhqqi4x', fcntl.F_WRLCK, os.SEEK_SET, 0, 0, 0))
    return fd


def check_live(driver, exe, run, shots, workdir):
    """A log still being written: the page shows "live", follows the end, then the summary."""
    src = os.path.join(run, 'frames.vlog')
    data, record = log_layout(src)
    with open(src, 'rb') as f:
        whole = f.read()
    frames = (len(whole) - data) // record
    live_dir = os.path.join(workdir, 'live')
    os.makedirs(live_dir)
    log = os.path.join(live_dir, 'frames.vlog')
    first = max(2, frames // 4)
    with open(log, 'wb') as f:
        f.write(whole[:data + first * record])
    claim = hold_run_claim(live_dir)
    server = Server(exe, [live_dir])
    writer = None
    stop = threading.Event()
    try:
        api = Api(server.url)
        page = Page(driver, api)
        page.open(api.page)
        page.wait(lambda d: d.find_element(By.ID, 'live-badge').is_displayed(), 'the live badge')
        R.check(True, 'live: a log without summary.json shows the live badge')
        page.keys(Keys.END)
        page.ready()
        t_start, _ = page.shown_time()

        def append():  # the rest of the log, a few frames at a time, as a run writes it
            with open(log, 'ab') as f:
                for k in range(first, frames, 40):
                    if stop.is_set():
                        return
                    f.write(whole[data + k * record:data + min(frames, k + 40) * record])
                    f.flush()
                    time.sleep(0.1)
        writer = threading.Thread(target=append, daemon=True)
        writer.start()
        page.wait(lambda d: page.shown_time()[0] > t_start + 1.0, 'the cursor to follow the growing log')
        R.check(True, 'live: the cursor at the end follows frames appended after start')
        page.shot(shots, 'live.png')
        writer.join(timeout=60)
        page.wait(lambda d: abs(page.shown_time()[0] - api.get('/api/run')['last_time']) < 1e-6,
                  'the cursor to reach the new end of the log')
        R.check(True, 'live: the cursor ends at the last appended frame')
        shutil.copy(os.path.join(run, 'summary.json'), os.path.join(live_dir, 'summary.json'))
        os.close(claim)  # the run ends: its summary written, its claim let go
        claim = None
        page.wait(lambda d: not d.find_element(By.ID, 'live-badge').is_displayed(), 'the live badge to go')
        R.check(True, 'live: the badge goes when summary.json appears')
        page.wait(lambda d: 'goal' in d.find_element(By.ID, 'summary').text, 'the summary to be shown')
        R.check(True, 'live: the summary is shown when it appears')
        # The run repeated into its directory (vascsim run --force): a new file under the log's
        # name. The server opens it again; the page, told so by the next frame, asks for a reload.
        with open(log + '.new', 'wb') as f:
            f.write(whole)
        os.replace(log + '.new', log)
        page.keys(Keys.HOME)
        page.wait(lambda d: 'reload the page' in d.find_element(By.ID, 'status-line').text,
                  'the page to ask for a reload')
        R.check(True, 'replaced: a log replaced on disk makes the page ask for a reload')
        page.shot(shots, 'replaced.png')
        page.open(api.page)
        R.check(page.js('return window.vascsimReplay.state().range[1]') == api.get('/api/run')['last_time']
                and api.get('/api/run')['generation'] == 1
                and 'reload' not in driver.find_element(By.ID, 'status-line').text,
                'replaced: after the reload the page shows the new log, without the message')
        page.collect_log()
        R.check(not page.severe, 'no JS errors in the browser log (live)', '; '.join(page.severe[:5]))
    finally:
        stop.set()
        if writer:
            writer.join(timeout=10)
        if claim is not None:
            os.close(claim)
        server.stop('live', driver)

# ---------------------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--vascsim', help='the vascsim executable')
    ap.add_argument('--run', help='run directory A')
    ap.add_argument('--run-b', help='run directory B (compare mode)')
    ap.add_argument('--run-c', help='a run in another environment than A (the overlay warning)')
    ap.add_argument('--probe', help='the MP4 probe: PROBE FILE prints {"codec", "frames", "width", "height", "duration"}')
    ap.add_argument('--screenshots', help='directory for screenshots')
    ap.add_argument('--url', help='development only: use this running server instead of starting vascsim')
    ap.add_argument('--url-b', help='development only: a running server in compare mode')
    args = ap.parse_args()
    if not args.url and not (args.vascsim and args.run):
        ap.error('--vascsim and --run are required (or --url for a running server)')
    if not args.url and not args.probe:
        ap.error('--probe is required when vascsim is started by the test')
    if args.screenshots:
        os.makedirs(args.screenshots, exist_ok=True)
    workdir = tempfile.mkdtemp(prefix='replay_browser_test_')
    started = time.time()
    driver = None
    server = None
    try:
        try:
            if args.url:
                url = args.url
            else:
                server = Server(args.vascsim, [args.run])
                url = server.url
            api = Api(url)
            driver = make_driver()
            page = Page(driver, api)
            section('page load', check_load, page, args.screenshots)
            section('token', check_token, api)
            section('scrub by keys', check_keys, page)
            section('scrub by dragging the timeline', check_drag, page)
            section('layer toggle', check_layers, page, args.screenshots)
            section('hover readout', check_hover, page, args.screenshots)
            section('plot readouts', check_plot_readouts, page, ['a'], 'plots')
            section('added plot', check_added_plot, page)
            section('zoom and pan', check_zoom_pan, page)
            section('playback', check_playback, page)
            section('deep link', check_deeplink, page, args.screenshots)
            section('bookmark', check_bookmark, page)
            section('help overlay', check_help, page, args.screenshots)
            section('export', check_export, page, args.screenshots, args.probe, workdir)
            page.collect_log()
            R.check(not page.severe, 'no JS errors in the browser log (single run)', '; '.join(page.severe[:5]))
            page.severe.clear()
            if server:
                server.stop('single run', driver)
                server = None
            if not args.url:
                section('live follow', check_live, driver, args.vascsim, args.run, args.screenshots, workdir)
                section('warnings', check_warnings, driver, args.vascsim, args.screenshots, workdir)
                section('stopped run', check_stopped_run, driver, args.vascsim, args.screenshots, workdir)
                section('killed run', check_killed_run, driver, args.vascsim, args.screenshots, workdir)
            if args.url_b or (args.vascsim and args.run_b and not args.url):
                if args.url_b:
                    url_b = args.url_b
                else:
                    server = Server(args.vascsim, [args.run, args.run_b])
                    url_b = server.url
                page_b = Page(driver, Api(url_b))
                section('compare mode', check_compare, page_b, args.screenshots)
                page_b.collect_log()
                R.check(not page_b.severe, 'no JS errors in the browser log (compare)', '; '.join(page_b.severe[:5]))
                if server:
                    server.stop('compare', driver)
                    server = None
                if args.run_c and not args.url:
                    server = Server(args.vascsim, [args.run, args.run_c])
                    page_c = Page(driver, Api(server.url))
                    section('overlay of a run in another environment', check_other_environment, page_c, args.screenshots)
                    R.check(not page_c.severe, 'no JS errors in the browser log (other environment)', '; '.join(page_c.severe[:5]))
                    server.stop('other environment', driver)
                    server = None
            else:
                R.skip('compare mode', 'no --run-b / --url-b')
        except CheckFailed as e:
            R.check(False, 'setup', str(e))
        except WebDriverException as e:
            R.check(False, 'browser', str(e).splitlines()[0] if str(e) else repr(e))
    finally:
        if driver:
            try:
                driver.quit()
            except WebDriverException:
                pass
        if server:
            server.proc.kill()
            server.proc.wait()
        shutil.rmtree(workdir, ignore_errors=True)
    print(f'({time.time() - started:.1f} s, {R.skipped} skipped)', flush=True)
    print(f'{R.passed} passed, {R.failed} failed', flush=True)
    return 1 if R.failed else 0


if __name__ == '__main__':
    sys.exit(main())
