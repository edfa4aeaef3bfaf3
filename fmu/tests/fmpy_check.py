#!/usr/bin/env python3
"""FMPy check of wrc.fmu (docs/fmu.md): validation, a 2 s co-simulation, comparison with the Rust API.

usage: fmpy_check.py FMU WORKDIR REFERENCE_EXE

1. fmpy.validate_fmu(FMU) must report no problem.
2. fmpy.simulate_fmu: dy = 4 sin(2 pi 1 Hz t) mm (towards the analysed wheel), yaw 0, fz 83300 N,
   given at every 1 ms point, step_size = output_interval = 1e-3 s, 0 ... 2 s; outputs written to
   WORKDIR/fmu.csv (time, dy, dy_used, fx, fy, mz, fn, n_patches, status). Every status must be 0.
3. REFERENCE_EXE (cargo example `reference`) evaluates wrc_kernel::step::step at the shifts the FMU
   used (dy_used) with the FMU's own resources/table.bin, into WORKDIR/reference.csv; fx, fy, mz, fn
   must agree to 1e-12 relative.
4. Cost: wall time of simulate_fmu / steps, and of a bare loop of fmi2SetReal + fmi2DoStep +
   fmi2GetReal through FMPy's FMU2Slave (host, microseconds per step).
Exits non-zero on any failure.
"""

import subprocess
import sys
import time
import zipfile
from pathlib import Path

import numpy as np
from fmpy import read_model_description, simulate_fmu, extract
from fmpy.fmi2 import FMU2Slave
from fmpy.validation import validate_fmu

REL = 1e-12
T_END = 2.0
H = 1e-3
FZ = 83300.0
OUTPUTS = ["dy_used", "fx", "fy", "mz", "fn", "n_patches", "status"]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    fmu, work, ref_exe = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
    work.mkdir(parents=True, exist_ok=True)
    failed = False

    # 1. validation
    problems = validate_fmu(str(fmu))
    if problems:
        print("FAIL: validate_fmu:")
        for p in problems:
            print("  ", p)
        return 1
    md = read_model_description(str(fmu))
    print(f"validate_fmu: no problems ({md.fmiVersion}, {len(md.modelVariables)} variables, GUID {md.guid})")

    # 2. simulation
    n = int(round(T_END / H))
    t = np.arange(n + 1) * H
    sig = np.zeros(n + 1, dtype=[("time", np.float64), ("dy", np.float64), ("yaw", np.float64), ("fz", np.float64)])
    sig["time"] = t
    sig["dy"] = 4.0 * np.sin(2.0 * np.pi * 1.0 * t)
    sig["yaw"] = 0.0
    sig["fz"] = FZ
    t0 = time.perf_counter()
    res = simulate_fmu(
        str(fmu),
        fmi_type="CoSimulation",
        start_time=0.0,
        stop_time=T_END,
        step_size=H,
        output_interval=H,
        input=sig,
        output=OUTPUTS,
    )
    wall = time.perf_counter() - t0
    steps = len(res) - 1
    dy_in = np.interp(res["time"], t, sig["dy"])
    with open(work / "fmu.csv", "w") as f:
        f.write("time,dy," + ",".join(OUTPUTS) + "\n")
        for i, r in enumerate(res):
            f.write(",".join(repr(float(x)) for x in [r["time"], dy_in[i]] + [r[o] for o in OUTPUTS]) + "\n")
    print(f"simulate_fmu: {len(res)} rows to {work / 'fmu.csv'}; {wall:.3f} s wall, "
          f"{wall / steps * 1e6:.1f} us per step (FMPy's loop included)")
    bad = res[res["status"] != 0]
    if len(bad):
        print(f"FAIL: {len(bad)} rows with status != 0, first at t = {bad['time'][0]}")
        failed = True
    if res["n_patches"].min() < 1:
        print("FAIL: a row without a contact patch")
        failed = True
    span = (res["dy_used"].min(), res["dy_used"].max())
    print(f"dy_used spans {span[0]:.4f} ... {span[1]:.4f} mm; fy {res['fy'].min():.1f} ... {res['fy'].max():.1f} N")
    if not (span[0] < -3.99 and span[1] > 3.99):
        print("FAIL: the FMU did not see the prescribed oscillation")
        failed = True

    # 3. the Rust API at the same states, same table bytes
    table = work / "table.bin"
    with zipfile.ZipFile(fmu) as z:
        table.write_bytes(z.read("resources/table.bin"))
    with open(work / "states.csv", "w") as f:
        f.write("time,dy_used,yaw,fz\n")
        for r in res:
            f.write(f"{float(r['time'])!r},{float(r['dy_used'])!r},0.0,{FZ!r}\n")
    subprocess.run([ref_exe, str(table), str(work / "states.csv"), str(work / "reference.csv")], check=True)
    ref = np.genfromtxt(work / "reference.csv", delimiter=",", names=True)
    if len(ref) != len(res):
        print(f"FAIL: reference has {len(ref)} rows, the FMU {len(res)}")
        return 1
    worst = 0.0
    for q in ["fx", "fy", "mz", "fn"]:
        a, b = res[q].astype(np.float64), ref[q]
        scale = np.abs(b)
        ok = np.abs(a - b) <= REL * scale
        rel = np.where(scale > 0, np.abs(a - b) / np.where(scale > 0, scale, 1.0), np.abs(a - b))
        worst = max(worst, float(rel.max()))
        if not ok.all():
            i = int(np.argmin(ok))
            print(f"FAIL: {q} differs at t = {res['time'][i]}: FMU {a[i]!r}, Rust {b[i]!r}")
            failed = True
        else:
            print(f"{q}: FMU = Rust API on all {len(a)} rows (max relative difference {rel.max():.1e})")

    # 4. a bare stepping loop through the C API
    unzip = extract(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    s = FMU2Slave(guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier,
                  instanceName="bench")
    s.instantiate()
    s.setupExperiment(startTime=0.0)
    s.enterInitializationMode()
    s.exitInitializationMode()
    ins, outs = [vr["dy"]], [vr["fx"], vr["fy"], vr["mz"]]
    dys = [float(x) for x in sig["dy"][:n]]
    t0 = time.perf_counter()
    for i in range(n):
        s.setReal(ins, [dys[i]])
        s.doStep(currentCommunicationPoint=i * H, communicationStepSize=H)
        s.getReal(outs)
    bare = time.perf_counter() - t0
    s.terminate()
    s.freeInstance()
    print(f"bare loop setReal + doStep + getReal through FMPy: {bare / n * 1e6:.1f} us per step ({n} steps)")

    # 5. a shift outside the table (12 mm towards the wheel from 50 to 80 ms) does not stop FMPy
    t5 = np.arange(101) * H
    u5 = np.zeros(len(t5), dtype=[("time", np.float64), ("dy", np.float64), ("fz", np.float64)])
    u5["time"], u5["fz"] = t5, FZ
    u5["dy"] = np.where((t5 > 0.05) & (t5 < 0.08), 12.0, 1.0)
    r5 = simulate_fmu(str(fmu), stop_time=0.1, step_size=H, output_interval=H, input=u5,
                      output=["dy_used", "fy", "fn", "status"])
    out = r5[r5["dy_used"] == 12.0]
    back = r5[(r5["time"] > (out["time"].max() if len(out) else 0.1)) & (r5["status"] == 0)]
    if len(r5) != 101 or len(out) == 0 or (out["status"] != 3).any() or (out["fn"] != 0).any() \
            or len(back) == 0:
        print("FAIL: outside the table: expected status 3, zero forces, completion and recovery")
        failed = True
    else:
        print(f"outside the table: {len(out)} steps with status 3 (OutOfRange) and zero forces; "
              f"the simulation completed and recovered (status 0 from t = {back['time'][0]:.3f} s)")

    if failed:
        print("FMPy check FAILED")
        return 1
    print(f"FMPy check passed (max relative difference FMU vs Rust API {worst:.1e})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
