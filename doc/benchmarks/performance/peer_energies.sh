#!/usr/bin/env bash
# Do PeriDeal and the LAMMPS peers compute the same physics? Runs lammps/lammps_{pmb,lps}_41.in
# and PeriDeal's {pmb,lps}_lattice_3d_peer.prm (the same lattice, volumes, velocities, influence
# function, no surface correction) and prints the kinetic and potential energies after 0, 100 and
# 200 steps side by side, per unit particle volume as LAMMPS prints them (its atom mass is the
# density), with their differences relative to the initial kinetic energy.
# usage: peer_energies.sh BUILD_DIR   (needs Debian's lammps: lmp)
set -euo pipefail
build=$(realpath "$1")
here=$(dirname "$(realpath "$0")")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for model in pmb lps; do
  lmp -in "$here/lammps/lammps_${model}_41.in" -log "lammps_$model.log" > /dev/null
  "$build/bin/perideal-solid" "$here/${model}_lattice_3d_peer.prm" > "perideal_$model.log"
  /usr/bin/python3 - "$model" "lammps_$model.log" "output-$model-lattice-3d-peer/statistics.csv" <<'PY'
import csv, re, sys
model, lammps_log, statistics = sys.argv[1:]
volume = 0.0005 ** 3  # the particle volume: LAMMPS's energies are per unit volume
text = open(lammps_log).read().split("Step KinEng PotEng TotEng")[-1]
peer = {int(m.group(1)): (float(m.group(2)), float(m.group(3)))
        for m in re.finditer(r"^\s*(\d+)\s+(\S+)\s+(\S+)\s+\S+\s*$", text, re.M)}
print(f"{model.upper()}: step | kinetic PeriDeal | LAMMPS | difference / E0 | "
      f"potential PeriDeal | LAMMPS | difference / E0  (E0: the initial kinetic energy)")
rows = list(csv.DictReader(open(statistics)))
e0 = float(rows[0]["kinetic_energy"]) / volume
for row in rows:
    step = int(float(row["step"]))
    ke, pe = float(row["kinetic_energy"]) / volume, float(row["strain_energy"]) / volume
    lke, lpe = peer[step]
    print(f"  {step:4d} | {ke:.8g} | {lke:.8g} | {abs(ke - lke) / e0:.1e} | "
          f"{pe:.8g} | {lpe:.8g} | {abs(pe - lpe) / e0:.1e}")
PY
done
