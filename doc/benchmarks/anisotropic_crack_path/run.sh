#!/usr/bin/env bash
# Crack path against material orientation: the edge-notched plate of anisotropic_crack_path.prm
# with the fibre (material axis 3) at alpha = 0, 15, ..., 90 deg from the notch, with isotropic
# fracture energy (elastic anisotropy alone) and with the fracture energy ratios 1, 1, 1.8 (a
# crack along the fibres costs G0, one across them 1.8 G0), each at dx = 0.5 mm (the file's)
# and 0.25 mm; then the studies of the horizon, the contrast and the lattice. Results go to
# results/<set>/alpha_<alpha>/ next to this script (run.prm, run.log, wall_time, particle
# output); postprocess.py prints the tables (angles, reference directions, wall times, the
# robustness of the measurement) and draws anisotropic_crack_path_angle.png,
# anisotropic_crack_path_horizon_angle.png, anisotropic_crack_path_lattice_angle.png and the
# damage maps *_damage_<set>.png. About 70 min on one core.
# usage: bash doc/benchmarks/anisotropic_crack_path/run.sh [BUILD_DIR]   (default: build)
# Environment:
#   ACP_SETS   the main sets (default "iso_dx0.5 iso_dx0.25 ratios_dx0.5 ratios_dx0.25"). A set
#              is KIND_dxSPACING[_mFACTOR][_clamped|_rotBETA]: KIND iso (ratios 1, 1, 1),
#              ratios (1, 1, 1.8), rVALUE (1, 1, VALUE) or pmb (isotropic `bond based`, one
#              run at alpha = 0, a control); SPACING in mm; FACTOR the horizon in spacings
#              (default 3: 3.015; m4 is 4.015); _clamped the grips hold x too; _rotBETA the
#              plate, notch and grips turned by BETA deg against the lattice (rotated_plate.py,
#              grips clamped).
#   ACP_STUDY  the study sets (default "ratios_dx0.5_m4 ratios_dx0.5_m5 r1.4_dx0.5
#              ratios_dx0.5_clamped ratios_dx0.5_rot15 ratios_dx0.5_rot30 iso_dx0.5_rot30
#              pmb_dx0.5_rot30" and the perturbed lattice: ratios_dx0.5, ratios_dx0.5_clamped,
#              ratios_dx0.5_rot30, iso_dx0.5, ratios_dx0.5_clamped_fit, ratios_dx0.5_rot30_fit,
#              ratios_dx0.5_clamped_m4, ratios_dx0.5_rot30_m4, ratios_dx0.25_clamped_m4 and
#              ratios_dx0.25_rot30_m4, each with _p0.5_s1, _s2, _s3); "" skips them.
#              More set options: _pEPS a perturbed lattice (<Lattice perturbation> = EPS),
#              _sSEED its <Perturbation seed>, _continuum the continuum calibration, _fit
#              <Surface correction method> = stiffness fit.
#   ACP_ANGLES (default "0 15 30 45 60 75 90"); ACP_NP MPI ranks per run (default 1: the wall
#              times in README.md are one rank); ACP_POSTPROCESS_ONLY=1: no runs, the tables
#              and plots of the results there are.
# Sets with unequal ratios need a perideal-solid that knows <Material/anisotropic bond based/
# Fracture energy ratios>; without it they are skipped with a message.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:-build}" && pwd)"
solver="$build/bin/perideal-solid"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
sets=${ACP_SETS:-iso_dx0.5 iso_dx0.25 ratios_dx0.5 ratios_dx0.25}
perturbed_sets=""
for seed in 1 2 3; do
  for kind in ratios_dx0.5 ratios_dx0.5_clamped ratios_dx0.5_rot30 iso_dx0.5 \
    ratios_dx0.5_clamped_fit ratios_dx0.5_rot30_fit ratios_dx0.5_clamped_m4 ratios_dx0.5_rot30_m4 \
    ratios_dx0.25_clamped_m4 ratios_dx0.25_rot30_m4; do
    perturbed_sets="$perturbed_sets ${kind}_p0.5_s$seed"
  done
done
study=${ACP_STUDY-ratios_dx0.5_m4 ratios_dx0.5_m5 r1.4_dx0.5 ratios_dx0.5_clamped ratios_dx0.5_rot15 ratios_dx0.5_rot30 iso_dx0.5_rot30 pmb_dx0.5_rot30 $perturbed_sets}
angles=${ACP_ANGLES:-0 15 30 45 60 75 90}
np=${ACP_NP:-1}
has_ratios=false
if "$solver" --print-parameters 2 2>/dev/null | grep "Fracture energy ratios" > /dev/null; then
  has_ratios=true
fi

# ratio_of KIND: the third fracture energy ratio of a set's kind.
ratio_of() {
  case "$1" in
    iso|pmb) echo 1 ;;
    ratios) echo 1.8 ;;
    r*) echo "${1#r}" ;;
  esac
}

# variant SET ALPHA: results/SET/alpha_ALPHA/run.prm, the benchmark's file with the material
# angle, the lattice spacing (output every 46 us), the horizon and the ratios of the set, and
# with _clamped the grips holding x too, with _rotBETA the plate turned by BETA degrees against
# the lattice (rotated_plate.py; grips clamped, alpha from the notch).
variant() {
  local set=$1 alpha=$2 dir="results/$1/alpha_$2"
  local kind=${set%%_*} rest=${set#*_dx}
  local dx_mm=${rest%%_*} m=3 beta=0 base=anisotropic_crack_path.prm clamped=false
  local perturbation=0 seed=1 calibration=discrete method=energy
  local option
  for option in $(echo "${rest#"$dx_mm"}" | tr '_' ' '); do
    case "$option" in
      m*) m=${option#m} ;;
      clamped) clamped=true ;;
      rot*) beta=${option#rot} ;;
      p*) perturbation=${option#p} ;;
      s*) seed=${option#s} ;;
      continuum) calibration=continuum ;;
      fit) method="stiffness fit" ;;
    esac
  done
  mkdir -p "results/$set"
  if [ "$beta" != 0 ]; then
    base="results/$set/plate.prm"
    [ -f "$base" ] || /usr/bin/python3 rotated_plate.py "$beta" "results/$set/plate"
  fi
  local interval
  interval=$(/usr/bin/python3 -c "print(round(400 * 0.5 / $dx_mm))")
  mkdir -p "$dir"
  {
    echo "include $base"
    echo "subsection Discretization"
    echo "  set Lattice spacing = ${dx_mm}e-3"
    echo "  set Horizon factor  = $m.015"
    echo "  set Lattice perturbation = $perturbation"
    echo "  set Perturbation seed    = $seed"
    echo "  set Surface correction method = $method"
    echo "end"
    echo "subsection Material"
    if [ "$kind" = pmb ]; then
      echo "  set Model = bond based"
      echo "  subsection bond based"
      echo "    set Young's modulus = 17e9"
      echo "  end"
    fi
    echo "  subsection anisotropic bond based"
    echo "    set Orientation = $((alpha + beta + 90)), 90, 0"
    echo "    set Fracture energy ratios = 1, 1, $(ratio_of "$kind")"
    echo "    set Calibration = $calibration"
    echo "  end"
    echo "end"
    if $clamped; then
      echo "subsection Boundary conditions"
      echo "  subsection top"
      echo "    set Components = x, y"
      echo "    set Function   = 0; 0.1 * min(1, t / 2e-5)"
      echo "  end"
      echo "  subsection anchor"
      echo "    set Region = bottom grip"
      echo "  end"
      echo "end"
    fi
    echo "subsection Output"
    echo "  set Directory       = $dir"
    echo "  set Output interval = $interval"
    echo "end"
  } > "$dir/run.prm"
}

# run_sets SET...: every angle of each set; prints the run directories on the last line.
run_sets() {
  local dirs=()
  for set in "$@"; do
    if [ "$(ratio_of "${set%%_*}")" != 1 ] && ! $has_ratios; then
      echo "== $set: skipped ($solver has no <Fracture energy ratios>)" >&2
      continue
    fi
    rm -rf "results/$set"
    local set_angles=$angles
    [ "${set%%_*}" = pmb ] && set_angles=0
    for alpha in $set_angles; do
      variant "$set" "$alpha"
      local dir="results/$set/alpha_$alpha"
      local start seconds
      start=$(date +%s.%N)
      mpirun -np "$np" "$solver" "$dir/run.prm" > "$dir/run.log"
      seconds=$(/usr/bin/python3 -c "print(f'{$(date +%s.%N) - $start:.1f}')")
      echo "$seconds" > "$dir/wall_time"
      echo "== $set alpha = $alpha: $(grep -E '^Particles' "$dir/run.log"), $(grep -E '^Broken bonds' "$dir/run.log"), $seconds s" >&2
      dirs+=("$dir")
    done
  done
  echo "${dirs[@]}"
}

if [ "${ACP_POSTPROCESS_ONLY:-0}" != 1 ]; then
  run_sets $sets $study > /dev/null
fi

# plot PREFIX SKIP OPTIONS SET...: postprocess.py OPTIONS over the runs of the sets that exist,
# the damage figures of the sets in SKIP (comma-separated) left out.
plot() {
  local prefix=$1 skip=$2 options=$3 dirs=()
  shift 3
  for set in "$@"; do
    for alpha in $angles; do
      if [ -f "results/$set/alpha_$alpha/particles.xdmf" ]; then
        dirs+=("results/$set/alpha_$alpha")
      fi
    done
  done
  if [ ${#dirs[@]} -gt 0 ]; then
    /usr/bin/python3 postprocess.py "${dirs[@]}" --plot "$prefix" --skip-damage "$skip" $options
  fi
}
if [ -n "$study" ]; then
  echo "== horizon and contrast: delta = 3, 4, 5 dx, ratios 1.8 and 1.4 (postprocess.py)"
  plot anisotropic_crack_path_horizon ratios_dx0.5,ratios_dx0.25 "" \
    ratios_dx0.5 ratios_dx0.25 ratios_dx0.5_m4 ratios_dx0.5_m5 r1.4_dx0.5
  echo "== lattice: grips clamped, the plate turned by 15 and 30 deg against the lattice"
  plot anisotropic_crack_path_lattice ratios_dx0.5_clamped,ratios_dx0.5_rot15 "" \
    ratios_dx0.5_clamped ratios_dx0.5_rot15 ratios_dx0.5_rot30 iso_dx0.5_rot30 \
    pmb_dx0.5_rot30
  echo "== perturbed lattice (epsilon = 1/2, seeds 1-3): grips free and clamped, plate turned 30 deg"
  skip=$(echo $perturbed_sets | tr ' ' '\n' | grep -v -E '^ratios_dx0.5(_rot30)?_p0.5_s1$' | tr '\n' ',')
  plot anisotropic_crack_path_perturbed "$skip" "" $perturbed_sets
fi
echo "== crack deflection angles (postprocess.py)"
plot anisotropic_crack_path "" --robustness $sets
