"""Reading the raw outputs the measuring tools leave in the work directory: key-value
lines (osg_render, paper_measure), shading_compare's summary and the state of a run."""
import json
import os
import re

import shell_numbers

STATE_FILE = "routes.json"


def read_text(path):
    """A file's text, or None when it cannot be read (as `cat` prints nothing then)."""
    try:
        with open(path, "rb") as stream:
            return stream.read().decode("utf-8", "surrogateescape")
    except OSError:
        return None


def value(key, path):
    """The second field of the first line whose first field is KEY; None without one."""
    text = read_text(path)
    if text is None:
        return None
    for line in shell_numbers.lines(text):
        words = shell_numbers.fields(line)
        if words and words[0] == key:
            return words[1] if len(words) > 1 else ""
    return None


def text_of(path):
    """A file as a command substitution gives it: trailing newlines dropped."""
    return (read_text(path) or "").rstrip("\n")


def file_size(path):
    return str(os.path.getsize(path))


def rows(path):
    """The field lists of every line of a file (none when it is missing)."""
    text = read_text(path)
    return [shell_numbers.fields(line) for line in shell_numbers.lines(text or "")]


_SHADING_CUTS = {
    "visible": (r"^visible difference ", r" %.*"),
    "silhouette": (r".*\(silhouette ", r" %.*"),
    "mean": (r".*mean \|dI\| ", r";.*"),
}


def shading_value(what, path):
    """One figure of shading_compare's summary line ("visible difference V % of covered
    pixels (silhouette S %), mean |dI| M; ..."); "" without that line."""
    text = read_text(path) or ""
    for line in shell_numbers.lines(text):
        if line.startswith("visible difference"):
            before, after = _SHADING_CUTS[what]
            line = re.sub(before, "", line, count=1, flags=re.DOTALL)
            return re.sub(after, "", line, count=1, flags=re.DOTALL)
    return ""


def path_range(exp2):
    """The camera path shared by every file: the nearest start and the farthest end of
    the two LOD sets' own paths (osg_render --no-render)."""
    nears, fars = [], []
    for name in ("paper", "chain"):
        for words in rows(os.path.join(exp2, name + ".path")):
            second = words[1] if len(words) > 1 else ""
            if words and words[0] == "path_near":
                nears.append(second)
            if words and words[0] == "path_far":
                fars.append(second)
    nears.sort(key=shell_numbers.general_numeric_key)
    fars.sort(key=shell_numbers.general_numeric_key)
    return (nears[0] if nears else "", fars[-1] if fars else "")


def save_state(work, state):
    """What the page needs from a run besides its raw outputs: the settings and the
    routes the simplifications and the LOD sets took."""
    with open(os.path.join(work, STATE_FILE), "w", encoding="utf-8") as stream:
        json.dump(state, stream, indent=1, ensure_ascii=False)
        stream.write("\n")


def load_state(work):
    with open(os.path.join(work, STATE_FILE), encoding="utf-8") as stream:
        return json.load(stream)
