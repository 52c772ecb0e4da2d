#!/usr/bin/env python3
"""Survey: mirage on POV-Ray 3.7's own example scenes (Debian package povray-examples).

For every example scene outside animations/ and portfolio/ it writes a wrapper that puts a
mirage in front of the scene,

    #declare Mirage_Preset = "hot-road";
    #include "mirage.inc"
    #include "/usr/share/doc/povray/examples/FOLDER/SCENE.pov"

and runs, each with a time limit (default 20 s):

  (a) mirage compile at 64x48; when it refuses the scene because the camera is below the
      ground and names a horizontal plane of the scene as the likely ground, once more with
      that Mirage_Ground_Height declared (what a user reading the message would do);
  (b) mirage trace --no-atmosphere and POV-Ray (no antialiasing) at 160x120, and the PSNR
      between the two images (OpenImageIO's idiff); a scene matches at PSNR >= 35 dB.
      A trace that runs out of time is tried again at 64x48, to tell slow from hung.

It prints per folder: scenes, accepted by compile, rendered by trace, matching POV-Ray, and
the main failure reasons (first error line, without its place, grouped), and writes
OUT/results.csv and OUT/summary.md.  Work files go to OUT/work/FOLDER/SCENE/.

    tools/example_scenes.py [--mirage build/mirage] [--out build/example_scenes] [--jobs 2]
                            [--only SUBSTRING ...] [--timeout 20] [--check SAMPLE.csv]

With --check, only the scenes of SAMPLE.csv (columns scene, compile, match: 1 when the
scene must be accepted by mirage compile, and must match POV-Ray at PSNR >= 35 dB) are run,
and the exit status says whether every expectation held (0), some did not (1) or the example
scenes are not installed (77, a skip for CTest).
"""

import argparse
import collections
import concurrent.futures
import csv
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

EXAMPLES = "/usr/share/doc/povray/examples"  # /usr/share/povray-3.7/scenes points here
SKIP_FOLDERS = ("animations", "portfolio")
MATCH_DB = 35.0
HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def find_scenes(root, only):
    scenes = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames.sort()
        rel = os.path.relpath(dirpath, root)
        top = rel.split(os.sep)[0]
        if top in SKIP_FOLDERS:
            continue
        for f in sorted(filenames):
            if not f.endswith(".pov"):
                continue
            path = os.path.join(dirpath, f)
            relpath = os.path.relpath(path, root)
            if only and not any(o in relpath for o in only):
                continue
            scenes.append(relpath)
    return sorted(scenes)


def run(cmd, cwd, timeout):
    """Runs cmd; returns (status, seconds, stdout, stderr); status 'ok', 'error', 'timeout'
    or 'crash (signal N)'."""
    start = time.monotonic()
    try:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             start_new_session=True)
    except OSError as e:
        return "error", 0.0, "", str(e)
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
        return "timeout", time.monotonic() - start, out.decode(errors="replace"), \
            err.decode(errors="replace")
    seconds = time.monotonic() - start
    out = out.decode(errors="replace")
    err = err.decode(errors="replace")
    if p.returncode < 0:
        return "crash (signal %d)" % -p.returncode, seconds, out, err
    if p.returncode > 1 and p.returncode >= 128:
        return "crash (exit %d)" % p.returncode, seconds, out, err
    return ("ok" if p.returncode == 0 else "error"), seconds, out, err


PLACE = re.compile(r"^(?:[^\s:]+:)?\d+:\d+: ")


def mirage_reason(text):
    """The first error line of a mirage command, its place replaced by the file's name."""
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith("trace ["):
            continue
        line = re.sub(r"^mirage \w+: ", "", line)
        m = re.match(r"^(\S+?):(\d+):(\d+): (.*)$", line)
        if m:
            name = os.path.basename(m.group(1))
            return "%s (in %s)" % (m.group(4), name if name.endswith(".inc") else "the scene")
        return line
    return "no message"


def povray_reason(text):
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if "Error" in line or "error:" in line:
            m = re.search(r"(Parse Error|Possible Parse Error|Error)\s*:?\s*(.*)", line)
            msg = m.group(0) if m else line.strip()
            if msg.strip().endswith(":") and i + 1 < len(lines):
                msg += " " + lines[i + 1].strip()
            return msg.strip()
    tail = [l for l in lines if l.strip()]
    return tail[-1].strip() if tail else "no message"


GROUND_HINT = re.compile(r"Mirage_Ground_Height = (-?[0-9.eE+-]+)")


def psnr(a, b):
    """PSNR in dB of two images of the same size (idiff), inf when identical, None when they
    cannot be compared."""
    p = subprocess.run(["idiff", "-a", a, b], stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    out = p.stdout.decode(errors="replace")
    m = re.search(r"Peak SNR = ([-+0-9.eEinfa]+)", out)
    if m:
        v = float(m.group(1))
        return math.inf if math.isnan(v) else v
    if out.strip().endswith("PASS") and "Mean error" not in out:
        return math.inf  # idiff prints no statistics for identical images
    return None


def wrapper_text(original, ground=None):
    lines = ['#declare Mirage_Preset = "hot-road";']
    if ground is not None:
        lines.append("#declare Mirage_Ground_Height = %s;" % ground)
    lines.append('#include "mirage.inc"')
    lines.append('#include "%s"' % original)
    return "\n".join(lines) + "\n"


def survey_scene(rel, args):
    folder = rel.split(os.sep)[0]
    original = os.path.join(EXAMPLES, rel)
    srcdir = os.path.dirname(original)
    name = os.path.splitext(os.path.basename(rel))[0]
    work = os.path.join(args.out, "work", os.path.dirname(rel), name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    wrap = os.path.join(work, name + ".pov")
    with open(wrap, "w") as f:
        f.write(wrapper_text(original))
    includes = os.path.join(REPO, "pov_includes")
    row = {"folder": folder, "scene": rel}

    # (a) compile at 64x48.
    cmd = [args.mirage, "compile", wrap, "-W", "64", "-H", "48", "-o",
           os.path.join(work, "compiled"), "-q", "-L", srcdir]
    status, secs, out, err = run(cmd, work, args.timeout)
    row["compile_seconds"] = "%.2f" % secs
    row["ground_height"] = ""
    if status == "error":
        hint = GROUND_HINT.search(err)
        if hint and "not above the ground" in err:
            ground = hint.group(1)
            wrap_g = os.path.join(work, name + "_ground.pov")
            with open(wrap_g, "w") as f:
                f.write(wrapper_text(original, ground))
            cmd[2] = wrap_g
            row["ground_height"] = ground
            status, secs, out, err = run(cmd, work, args.timeout)
            row["compile_seconds"] = "%.2f" % secs
    row["compile"] = status
    row["compile_error"] = "" if status == "ok" else (
        mirage_reason(err) if status == "error" else status)
    row["camera_below_ground"] = "1" if status == "error" and "not above the ground" in err else "0"

    # (b) trace and POV-Ray at 160x120.
    trace_png = os.path.join(work, "trace.png")
    cmd = [args.mirage, "trace", wrap, "-W", "160", "-H", "120", "--no-atmosphere", "-o",
           trace_png, "-q", "--threads", "1", "-L", srcdir]
    status, secs, out, err = run(cmd, work, args.timeout)
    row["trace_seconds"] = "%.2f" % secs
    row["trace"] = status
    row["trace_error"] = "" if status == "ok" else (
        mirage_reason(err) if status == "error" else status)
    row["trace_small"] = ""
    if status == "timeout":
        small = [c if c not in ("160", "120") else ("64" if c == "160" else "48") for c in cmd]
        small[small.index(trace_png)] = os.path.join(work, "trace_small.png")
        s2, _, _, err2 = run(small, work, args.timeout)
        row["trace_small"] = s2

    pov_png = os.path.join(work, "povray.png")
    cmd = ["povray", wrap, "+W160", "+H120", "-D", "-A", "+FN", "+O" + pov_png, "+WT1",
           "+L" + srcdir, "+L" + includes, "-GS", "-GR"]
    status, secs, out, err = run(cmd, work, args.timeout)
    row["povray_seconds"] = "%.2f" % secs
    if status == "ok" and not os.path.exists(pov_png):
        status = "error"
    row["povray"] = status
    row["povray_error"] = "" if status == "ok" else (
        povray_reason(err + out) if status == "error" else status)

    row["psnr_db"] = ""
    row["match"] = "0"
    if row["trace"] == "ok" and row["povray"] == "ok":
        v = psnr(trace_png, pov_png)
        if v is not None:
            row["psnr_db"] = "inf" if math.isinf(v) else "%.2f" % v
            row["match"] = "1" if v >= MATCH_DB else "0"
    if not args.keep:
        for f in os.listdir(work):
            p = os.path.join(work, f)
            if os.path.isdir(p):
                shutil.rmtree(p, ignore_errors=True)
    return row


FIELDS = ["folder", "scene", "compile", "compile_error", "ground_height", "camera_below_ground",
          "compile_seconds", "trace", "trace_error", "trace_small", "trace_seconds", "povray",
          "povray_error", "povray_seconds", "psnr_db", "match"]


def reason_of_mismatch(row):
    if row["trace"] != "ok":
        return "trace: " + row["trace_error"]
    if row["povray"] != "ok":
        return "POV-Ray: " + row["povray_error"]
    return "PSNR below %g dB" % MATCH_DB


def summarise(rows, args, elapsed):
    folders = collections.OrderedDict()
    for r in sorted(rows, key=lambda r: r["scene"]):
        folders.setdefault(r["folder"], []).append(r)

    def counts(rs):
        n = len(rs)
        comp = sum(r["compile"] == "ok" for r in rs)
        below = sum(r["camera_below_ground"] == "1" for r in rs)
        ground = sum(r["compile"] == "ok" and r["ground_height"] != "" for r in rs)
        trace = sum(r["trace"] == "ok" for r in rs)
        pov = sum(r["povray"] == "ok" for r in rs)
        match = sum(r["match"] == "1" for r in rs)
        hung = sum(r["compile"] in ("timeout",) or r["compile"].startswith("crash") or
                   r["trace"].startswith("crash") or r["trace_small"] == "timeout" or
                   r["trace_small"].startswith("crash") for r in rs)
        return n, comp, ground, below, trace, pov, match, hung

    lines = []
    lines.append("| folder | scenes | compile accepts | (with the suggested ground) | camera "
                 "below its ground | trace renders | POV-Ray renders | match POV-Ray "
                 "(PSNR >= 35 dB) | crash or hang |")
    lines.append("|---|---|---|---|---|---|---|---|---|")
    total = [0] * 8
    for folder, rs in folders.items():
        c = counts(rs)
        total = [a + b for a, b in zip(total, c)]
        lines.append("| %s | %d | %d | %d | %d | %d | %d | %d | %d |" % ((folder,) + c))
    n, comp, ground, below, trace, pov, match, hung = total
    lines.append("| **all** | **%d** | **%d** | %d | %d | **%d** | %d | **%d** | %d |" %
                 (n, comp, ground, below, trace, pov, match, hung))

    def pct(a, b):
        return "%.1f %%" % (100.0 * a / b) if b else "-"

    summary = []
    summary.append("")
    summary.append("- compile accepts %d of %d scenes (%s); of the %d whose camera is above "
                   "the ground they declare: %s" % (comp, n, pct(comp, n), n - below,
                                                     pct(comp, n - below)))
    summary.append("- trace renders %d (%s); matches POV-Ray in %d of all %d scenes (%s)" %
                   (trace, pct(trace, n), match, n, pct(match, n)))
    summary.append("- crashes or hangs: %d" % hung)

    def reasons(key_fn, filt):
        c = collections.Counter(key_fn(r) for r in rows if filt(r))
        return c.most_common(args.reasons)

    blocks = []
    blocks.append(("compile refuses", reasons(
        lambda r: r["compile_error"], lambda r: r["compile"] != "ok")))
    blocks.append(("trace refuses", reasons(
        lambda r: r["trace_error"], lambda r: r["trace"] != "ok")))
    blocks.append(("no match", reasons(reason_of_mismatch, lambda r: r["match"] != "1")))
    text = []
    for title, rs in blocks:
        text.append("")
        text.append("Main reasons, %s (scenes: first error line):" % title)
        text.append("")
        for reason, k in rs:
            text.append("- %d: %s" % (k, reason.replace("|", "\\|")))
    low = sorted((r for r in rows if r["psnr_db"] not in ("", "inf") and r["match"] == "0"),
                 key=lambda r: float(r["psnr_db"]))
    if low:
        text.append("")
        text.append("Rendered by both but below %g dB: %s" % (MATCH_DB, ", ".join(
            "%s (%s)" % (r["scene"], r["psnr_db"]) for r in low)))
    footer = ["", "Measured by `%s` in %.0f s." % (" ".join(
        ["tools/example_scenes.py"] + sys.argv[1:]), elapsed)]
    return "\n".join(lines + summary + text + footer) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--mirage", default=os.path.join(REPO, "build", "mirage"))
    ap.add_argument("--out", default=os.path.join(REPO, "build", "example_scenes"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per command")
    ap.add_argument("--only", nargs="*", default=[], help="scenes whose path contains one of these")
    ap.add_argument("--reasons", type=int, default=12, help="reasons listed per kind")
    ap.add_argument("--keep", action="store_true", help="keep the compiled scenes")
    ap.add_argument("--check", help="a CSV of scenes with their expectations (see above)")
    args = ap.parse_args()
    args.mirage = os.path.abspath(args.mirage)
    args.out = os.path.abspath(args.out)
    if not os.path.isdir(EXAMPLES):
        print("no example scenes in %s: apt-get install povray-examples" % EXAMPLES,
              file=sys.stderr)
        sys.exit(77 if args.check else 1)
    if not os.access(args.mirage, os.X_OK):
        sys.exit("%s: not built (make build)" % args.mirage)
    expectations = {}
    if args.check:
        with open(args.check, newline="") as f:
            for r in csv.DictReader(l for l in f if not l.startswith("#")):
                expectations[r["scene"]] = r
        scenes = sorted(expectations)
        missing = [s for s in scenes if not os.path.exists(os.path.join(EXAMPLES, s))]
        if missing:
            sys.exit("%s: not among the example scenes: %s" % (args.check, ", ".join(missing)))
    else:
        scenes = find_scenes(EXAMPLES, args.only)
    os.makedirs(args.out, exist_ok=True)
    start = time.monotonic()
    rows = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(survey_scene, s, args): s for s in scenes}
        for i, fut in enumerate(concurrent.futures.as_completed(futures)):
            row = fut.result()
            rows.append(row)
            print("[%3d/%d] %-40s compile %-8s trace %-8s povray %-8s psnr %s" % (
                i + 1, len(scenes), row["scene"], row["compile"], row["trace"], row["povray"],
                row["psnr_db"] or "-"), file=sys.stderr, flush=True)
    rows.sort(key=lambda r: r["scene"])
    elapsed = time.monotonic() - start
    tmp = os.path.join(args.out, "results.csv.tmp")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    os.replace(tmp, os.path.join(args.out, "results.csv"))
    md = summarise(rows, args, elapsed)
    tmp = os.path.join(args.out, "summary.md.tmp")
    with open(tmp, "w") as f:
        f.write(md)
    os.replace(tmp, os.path.join(args.out, "summary.md"))
    print(md)
    if args.check:
        failures = []
        for r in rows:
            e = expectations[r["scene"]]
            if e["compile"] == "1" and r["compile"] != "ok":
                failures.append("%s: mirage compile: %s" % (r["scene"], r["compile_error"]))
            if r["compile"].startswith("crash") or r["trace"].startswith("crash"):
                failures.append("%s: a command crashed" % r["scene"])
            if e["match"] == "1" and r["match"] != "1":
                failures.append("%s: no match with POV-Ray (PSNR %s; %s)" % (
                    r["scene"], r["psnr_db"] or "-", reason_of_mismatch(r)))
        for f in failures:
            print("FAILED " + f, file=sys.stderr)
        print("%d scenes, %d expectations failed" % (len(rows), len(failures)), file=sys.stderr)
        sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
