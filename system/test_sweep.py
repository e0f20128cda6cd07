"""Sweep tool checks (run by tests/sweep.rs; argv: repo root): a small sweep on a
2-worker Dask LocalCluster gives exactly the numbers of the same runs made
serially, and a failing point is a row of the table, not the end of the sweep."""
import os
import sys

root = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
sys.path.insert(0, os.path.join(root, "system"))
from dask.distributed import Client, LocalCluster  # noqa: E402
from sweep import run_sweep  # noqa: E402

def main():
    fmu = os.path.join(root, "out", "jeffcott.fmu")
    rpms = [6000.0, 10000.0]
    params = {"unbalance.disk": [2e-5, 20.0]}  # 20 kg·m drives the journal into the clearance
    serial = run_sweep(fmu, rpms, params, 0.3, 5e-4)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, Client(cluster) as client:
        parallel = run_sweep(fmu, rpms, params, 0.3, 5e-4, client)
    failures = []
    if [r for r in serial] != [r for r in parallel]:
        failures.append("the 2-worker LocalCluster sweep differs from the serial one")
    bad = [r for r in parallel if r["status"] != "ok"]
    good = [r for r in parallel if r["status"] == "ok"]
    if not bad or not all(r["unbalance.disk"] == 20.0 for r in bad):
        failures.append(f"the 20 kg·m points must fail and be reported: {[(r['rpm'], r['status'][:60]) for r in parallel]}")
    if len(good) != 2 or any(r["unbalance.disk"] != 2e-5 for r in good):
        failures.append("the normal points must succeed")
    print(f"{len(parallel)} points, {len(bad)} reported failures: " + "; ".join(r["status"][:80] for r in bad))
    if failures:
        sys.exit("\n".join(failures))
    print("sweep: LocalCluster equals serial; failures reported in the table")


if __name__ == "__main__":
    main()
