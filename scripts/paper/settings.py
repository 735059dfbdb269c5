"""What a run of the paper reproduction works on: paths, settings from the environment
and the names of the filters it runs."""
import os
from dataclasses import dataclass

STOCK_FILTER = "Simplification: Quadric Edge Collapse Decimation"
CAD_FILTER = "Simplification: CAD Quadric Edge Collapse (compactness)"
LOD_FILTER = "Generate CAD LOD Set"
LEVELS = "50 60 70 80 90"

# Filter scripts list only what differs from the defaults; cadlod_mlx_complete fills in every
# other parameter (meshlabserver 2020.09 aborts otherwise). The CAD simplification filter's
# stop criterion, the face-count criterion off:
CAD_REDUCTION_PARAMS = ('<Param type="RichInt" name="targetFaces" value="0"/>'
                        '<Param type="RichFloat" name="reductionPerc" value="%s"/>')
# The LOD-set filter with one level, for a plugin without the CAD simplification filter:
LOD_ONE_LEVEL_PARAMS = ('<Param type="RichEnum" name="levelMode" enum_cardinality="2" value="1" '
                        'enum_val0="By screen-space error (VR)" enum_val1="Level list (the paper)"/>'
                        '<Param type="RichString" name="levels" value="%s"/>')


@dataclass
class Settings:
    root: str  # the repository
    build: str  # CADLOD_BUILD_DIR as given (relative to the current directory)
    frames: str  # frames per frame-rate run
    runs: str  # runs per figure, median kept

    @property
    def work(self):
        return os.path.join(self.build, "paper-reproduction")

    @property
    def img(self):
        return os.path.join(self.root, "docs", "img")

    @property
    def doc(self):
        return os.path.join(self.root, "docs", "paper-reproduction.md")

    @property
    def shaft(self):
        return os.path.join(self.root, "docs", "sample", "shaft.wrl")

    @property
    def assembly(self):
        return os.path.join(self.root, "docs", "sample", "cad_assembly.wrl.gz")

    def bench(self, name):
        """A file of the repository's bench/paper folder."""
        return os.path.join(self.root, "bench", "paper", name)


def from_environment(root):
    return Settings(root=root,
                    build=os.environ.get("CADLOD_BUILD_DIR") or os.path.join(root, "build"),
                    frames=os.environ.get("PAPER_FRAMES") or "300",
                    runs=os.environ.get("PAPER_RUNS") or "5")
