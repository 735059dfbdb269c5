"""Running the tools of the paper reproduction: the build, a private Xvfb, the staged
meshlabserver, osg_render, paper_measure, shading_compare and the picture tools."""
import os
import subprocess
import sys
import time


def say(message):
    print("[paper] %s" % message, file=sys.stderr, flush=True)


def die(message):
    say("ERROR: %s" % message)
    sys.exit(1)


def run(argv, stdout=None, stderr=None, append=False, timeout=None, env=None):
    """Runs ARGV with its output to files (paths; None keeps ours); True when it exits 0."""
    mode = "ab" if append else "wb"
    out = open(stdout, mode) if stdout else None
    err = (out if stderr == stdout else open(stderr, "ab")) if stderr else None
    try:
        return subprocess.run(argv, stdout=out, stderr=err, timeout=timeout, env=env, check=False).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False
    finally:
        for stream in {out, err} - {None}:
            stream.close()


def must(argv, **kwargs):
    """Runs a step the page cannot do without (a picture tool): stops the run when it fails."""
    if not run(argv, **kwargs):
        die("%s failed" % os.path.basename(argv[0]))


def nonempty(path):
    return os.path.isfile(path) and os.path.getsize(path) > 0


class Tools:
    def __init__(self, settings):
        self.settings = settings
        work, build = settings.work, settings.build
        self.mls_log = os.path.join(work, "meshlabserver.log")
        self.render_log = os.path.join(work, "render.log")
        self.mls_binary = os.path.join(build, "stage", "bin", "meshlabserver")
        self.plugins = os.path.join(build, "stage", "lib", "x86_64-linux-gnu", "meshlab", "plugins")
        self.render_binary = os.path.join(build, "bench", "paper", "osg_render")
        self.measure_binary = os.path.join(build, "bench", "paper", "paper_measure")
        self.shading_binary = os.path.join(build, "bench", "shading", "shading_compare")
        self.mlx_complete = None
        self.filters = ""
        self.xvfb = None

    # ------------------------------------------------------------ set-up
    def build(self):
        build, log = self.settings.build, os.path.join(self.settings.work, "build.log")
        generator = [] if os.path.isfile(os.path.join(build, "CMakeCache.txt")) else ["-G", "Ninja"]
        say("configuring and building in %s (stage, osg_render, paper_measure, shading_compare, cadlod_mlx_complete)"
            % build)
        if not run(["cmake", "-S", self.settings.root, "-B", build] + generator
                   + ["-DCADLOD_BUILD_BENCH=ON", "-DCADLOD_BUILD_TESTS=ON"], stdout=log, stderr=log):
            die("cmake configure failed, see %s" % log)
        if not run(["cmake", "--build", build, "--target", "stage", "osg_render", "paper_measure",
                    "shading_compare", "cadlod_mlx_complete", "-j2"], stdout=log, stderr=log, append=True):
            die("build failed, see %s" % log)
        self.mlx_complete = self._find_mlx_complete()
        if not self.mlx_complete:
            die("cadlod_mlx_complete was not built")

    def _find_mlx_complete(self):
        for folder, _, names in os.walk(os.path.join(self.settings.build, "tests")):
            path = os.path.join(folder, "cadlod_mlx_complete")
            if "cadlod_mlx_complete" in names and os.path.isfile(path) and os.access(path, os.X_OK):
                return path
        return None

    def start_xvfb(self):
        work = self.settings.work
        display_file = os.path.join(work, "display")
        with open(display_file, "wb") as display, open(os.path.join(work, "xvfb.log"), "wb") as log:
            self.xvfb = subprocess.Popen(
                ["Xvfb", "-displayfd", str(display.fileno()), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                 "-noreset"], stdout=log, stderr=log, pass_fds=[display.fileno()])
        for _ in range(50):
            if nonempty(display_file):
                break
            time.sleep(0.1)
        if not nonempty(display_file):
            die("Xvfb did not start (see %s)" % os.path.join(work, "xvfb.log"))
        with open(display_file) as display:
            os.environ["DISPLAY"] = ":" + display.read().replace("\n", "")
        say("Xvfb on %s" % os.environ["DISPLAY"])

    def stop_xvfb(self):
        if self.xvfb is not None and self.xvfb.poll() is None:
            self.xvfb.terminate()
            self.xvfb.wait()

    def list_filters(self):
        listing = os.path.join(self.settings.work, "filters.txt")
        run([self.mls_binary, "-d", listing], stdout=os.devnull, stderr=os.devnull, timeout=120)
        if not nonempty(listing):
            die("meshlabserver cannot list its filters (see %s)" % listing)
        with open(listing, "rb") as stream:
            self.filters = stream.read().decode("utf-8", "surrogateescape")

    # ------------------------------------------------------------ MeshLab
    def mls(self, *args):
        """meshlabserver ARGS: with a timeout, because a dialog would block it for ever; no
        qDebug, which would echo every log line into the log a second time ("LOG: ...")."""
        with open(self.mls_log, "ab") as log:
            log.write(("== meshlabserver %s\n" % " ".join(args)).encode("utf-8", "surrogateescape"))
        env = dict(os.environ, QT_LOGGING_RULES="*.debug=false")
        return run([self.mls_binary] + list(args), stdout=self.mls_log, stderr=self.mls_log, append=True,
                   timeout=900, env=env)

    def complete_mlx(self, partial, out):
        """PARTIAL with every parameter the staged plugins define (defaults for those it leaves
        out); False when it names a filter or parameter the plugins lack."""
        return run([self.mlx_complete, self.plugins, partial, out], stdout=self.mls_log, stderr=self.mls_log,
                   append=True)

    def single_filter_mlx(self, out, filter_name, params=""):
        """A completed one-filter script."""
        with open(out + ".partial", "w", encoding="utf-8") as stream:
            stream.write('<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name="%s">\n  %s\n </filter>\n'
                         '</FilterScript>\n' % (filter_name, params))
        return self.complete_mlx(out + ".partial", out)

    def has_filter(self, name):
        return "section f" in self.filters and " %s " % name in self.filters

    # ------------------------------------------------------------ measures
    def render(self, args, out, append=False):
        """osg_render ARGS, its output to OUT, its complaints to render.log."""
        return run([self.render_binary] + list(args), stdout=out, stderr=self.render_log, append=append)

    def measure(self, args, out):
        return run([self.measure_binary] + list(args), stdout=out)

    def shading(self, args, out):
        return run([self.shading_binary] + list(args), stdout=out)
