#!/usr/bin/env python3
"""Runs each VRML reader on each file in a fresh process and prints the table (bench/vrml/run.sh)."""
import argparse, os, re, subprocess

def run_child(cmd, timeout):
    # Each measurement in its own python child so RUSAGE_CHILDREN is this command alone.
    script = ("import os,sys,subprocess,resource,time,signal\n"
              "t=time.monotonic()\n"
              "p=subprocess.Popen(sys.argv[2:],stdout=subprocess.PIPE,stderr=subprocess.STDOUT,start_new_session=True)\n"
              "try:\n out,_=p.communicate(timeout=float(sys.argv[1])); c=p.returncode\n"
              "except subprocess.TimeoutExpired:\n os.killpg(p.pid,9); out,_=p.communicate(); c='timeout'\n"
              "w=time.monotonic()-t\n"
              "r=resource.getrusage(resource.RUSAGE_CHILDREN)\n"
              "sys.stdout.write(f'@@ {w:.3f} {r.ru_utime+r.ru_stime:.3f} {r.ru_maxrss/1024:.0f} {c}\\n')\n"
              "sys.stdout.write(out.decode(errors='replace'))\n")
    res = subprocess.run(["python3", "-c", script, str(timeout)] + cmd, capture_output=True, text=True)
    head, _, out = res.stdout.partition("\n")
    _, wall, cpu, rss, code = head.split()
    return float(wall), float(cpu), float(rss), code, out

def triangles(reader, out):
    pats = {"core": r"^\S+\t\S+\t\S+\t(\d+)", "plugin": r"loaded has \d+ vn (\d+) fn",
            "io_x3d": r"loaded has \d+ vn (\d+) fn", "coin": r"\tmesh (\d+)"}
    m = re.search(pats[reader], out, re.M)
    return int(m.group(1)) if m else None

def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("files", nargs="+")
    a = ap.parse_args()
    readers = [
        ("core", "cadlod core", lambda f: [f"{a.build}/bench/vrml/vrml_core_bench", f]),
        ("plugin", "cadlod plugin (meshlabserver)", lambda f: [f"{a.build}/stage/bin/meshlabserver", "-i", f]),
        ("io_x3d", "MeshLab io_x3d (meshlabserver)", lambda f: ["/usr/bin/meshlabserver", "-i", f]),
        ("coin", "Coin3D 4 (readAll + triangles)", lambda f: [f"{a.build}/tests/vrml/coin_count", f]),
    ]
    # Start-up cost of each reader (meshlabserver loads ~280 plugins): one triangle file.
    tiny = os.path.join(os.path.dirname(os.path.abspath(a.files[0])), "tiny.wrl")
    with open(tiny, "w") as t:
        t.write("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } "
                "coordIndex [ 0 1 2 ] } }\n")
    startup = {key: run_child(cmd(tiny), a.timeout)[:2] for key, _, cmd in readers}
    print("net = minus the reader's start-up on a one-triangle file: " +
          ", ".join(f"{k} {w:.2f} s wall / {c:.2f} s cpu" for k, (w, c) in startup.items()))
    print(f"{'file':>10} {'reader':<32} {'wall s':>7} {'cpu s':>7} {'MB/s wall':>9} {'MB/s cpu':>9} "
          f"{'net MB/s':>9} {'triangles':>10} {'Mtri/s net':>10} {'peak MB':>8}")
    for f in a.files:
        mb = os.path.getsize(f) / 1e6
        for key, name, cmd in readers:
            wall, cpu, rss, code, out = run_child(cmd(f), a.timeout)
            tris = triangles(key, out)
            if code != "0" or tris is None:
                print(f"{mb:>8.1f}MB {name:<32} {'failed: ' + code:>7}")
                continue
            net = max(cpu - startup[key][1], 1e-3)
            print(f"{mb:>8.1f}MB {name:<32} {wall:>7.2f} {cpu:>7.2f} {mb / wall:>9.1f} {mb / cpu:>9.1f} "
                  f"{mb / net:>9.1f} {tris:>10} {tris / net / 1e6:>10.2f} {rss:>8.0f}", flush=True)

if __name__ == "__main__":
    main()
