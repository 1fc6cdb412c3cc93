"""What the job scripts share (jobscripts/sweep, jobscripts/scaling): the program, its MPI launcher, the checks of
every run before anything runs or is submitted, and SLURM time requests from the estimates."""
import os
import re
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("HALFETI_BUILD") or os.path.join(ROOT, "build")  # the build folder (HALFETI_BUILD)
HALFETI = os.path.join(BUILD, "src", "app", "halfeti")


def mpi_env():
    """The environment of a local run (Open MPI as root, more ranks than cores)."""
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                OMPI_MCA_rmaps_base_oversubscribe="1")


def run_alone(cmd):
    """subprocess.run(cmd) for a halfeti process started beside others at the same moment (`check` and `compare`
    of many points at once): each gets its own Open MPI session folder. Open MPI 4.1 creates one per user and
    host under /tmp at start-up, and two processes creating it together can fail ("A call to mkdir was unable to
    create the desired directory ... File exists")."""
    folder = tempfile.mkdtemp(prefix="halfeti-ompi-")
    try:
        return subprocess.run(cmd, capture_output=True, text=True,
                              env=dict(os.environ, OMPI_MCA_orte_tmpdir_base=folder))
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def default_launcher():
    """srun inside a SLURM allocation, mpirun elsewhere."""
    return "srun" if os.environ.get("SLURM_JOB_ID") else "mpirun"


def launch_prefix(launcher, ranks):
    """The command that starts `ranks` ranks (Debian's Open MPI needs srun's PMIx)."""
    if launcher == "srun":
        return ["srun", "--mpi=pmix", "-n", str(ranks)]
    return ["mpirun", "-n", str(ranks)]


def is_slurm_time(text):
    return re.fullmatch(r"([0-9]+-)?[0-9]+(:[0-9]{2}){0,2}", text) is not None


def slurm_time(seconds):
    """A time request of three times the estimate plus 5 minutes, as HH:MM:00."""
    minutes = int(3 * seconds / 60) + 5
    return f"{minutes // 60:02d}:{minutes % 60:02d}:00"


def check(points):
    """`halfeti check` of every (scene, [--set values]) point, as many at once as there are cores. Returns, per
    point, (its CompletedProcess, its estimated wall seconds on one rank, its estimated particles); a scene
    without water has no estimate (0)."""
    def one(point):
        scene, sets = point
        return run_alone([HALFETI, "check", scene] + sum((["--set", s] for s in sets), []))
    with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        results = list(pool.map(one, points))
    out = []
    for r in results:
        wall = re.search(r"about ([0-9.e+]+) s of wall time", r.stdout)
        particles = re.search(r"about ([0-9.e+]+) particles", r.stdout)
        out.append((r, float(wall.group(1)) if wall else 0.0, float(particles.group(1)) if particles else 0.0))
    return out
