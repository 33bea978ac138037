#!/usr/bin/env python3
"""local_resample_test.py AMLS SCENE WORK_DIR: `--resample local`, end to end.

- The single vortex at 128^2 under `local` runs all 800 steps, ends closed,
  resamples somewhere on some steps only, reports its strain limit (0.05), and
  its L1 error is within 25 % of
  the default policy's (measured: docs/local-resampling.md).
- A short `amls deform SCENE --resample local` reports the policy and stays
  as close to the exact deformed shape as under `always`.
- `local` with the ray-tracing baseline fails before any work, naming the option.
"""
import json
import os
import subprocess
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(amls, *args):
    r = subprocess.run([amls, *args], capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"amls {' '.join(args)} exited {r.returncode}:\n{r.stdout}{r.stderr}")
    return r.stdout


def report(path):
    with open(path) as f:
        return json.load(f)


def main():
    amls, scene, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)

    always_path, local_path = os.path.join(work, "always.json"), os.path.join(work, "local.json")
    run(amls, "vortex", "--grid", "128", "--json", always_path)
    run(amls, "vortex", "--grid", "128", "--resample", "local", "--json", local_path)
    always, local = report(always_path), report(local_path)
    if local["resample"] != "local" or local["status"] != "ok" or local["steps"] != 800:
        fail(f"vortex under local: policy {local['resample']}, status {local['status']}, {local['steps']} steps")
    if local["strain_limit"] != 0.05:
        fail(f"vortex under local: strain_limit {local['strain_limit']} in the report, expected 0.05")
    if not 0 < local["resamples"] < 800:
        fail(f"vortex under local resampled on {local['resamples']} of 800 steps: expected some, not all")
    ratio = local["l1_error"] / always["l1_error"]
    print(f"vortex 128^2: L1 {local['l1_error']:.4g} under local, {always['l1_error']:.4g} under always "
          f"({ratio:.3f}x), {local['resamples']} steps resampled somewhere")
    if not ratio <= 1.25:
        fail(f"vortex under local: L1 {local['l1_error']} is {ratio:.2f} times the default's {always['l1_error']}")

    deform_always, deform_local = os.path.join(work, "deform_always.json"), os.path.join(work, "deform_local.json")
    run(amls, "deform", scene, "--max-steps", "8", "--tracers", "4", "--json", deform_always)
    run(amls, "deform", scene, "--max-steps", "8", "--tracers", "4", "--resample", "local", "--json", deform_local)
    a, l = report(deform_always), report(deform_local)
    if l["resample"] != "local" or l["status"] != "ok" or l["steps"] != 8:
        fail(f"deform under local: policy {l['resample']}, status {l['status']}, {l['steps']} steps")
    if l["distance_to_exact_h"]["max"] > 1.25 * a["distance_to_exact_h"]["max"] + 0.05:
        fail(f"deform under local: {l['distance_to_exact_h']['max']} h from the exact shape, "
             f"against {a['distance_to_exact_h']['max']} h under always")

    r = subprocess.run([amls, "vortex", "--grid", "32", "--variant", "raytrace", "--resample", "local"],
                       capture_output=True, text=True)
    if r.returncode == 0 or "--resample local needs --variant exact or interpolated" not in r.stdout + r.stderr:
        fail(f"vortex --variant raytrace --resample local: exit {r.returncode}, said:\n{r.stdout}{r.stderr}")
    print("--resample local: vortex and deform run and stay close to the default; raytrace is refused")


if __name__ == "__main__":
    main()
