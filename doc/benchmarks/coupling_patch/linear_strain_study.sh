#!/usr/bin/env bash
# Static linear-strain patch tests of the blended coupling: the plate of static.prm with
# every FE boundary held to the quadratic field u = a (x^2 + x y, (2 x^2 + y^2) / 2), a = 1e-3 1/m,
# and the constant body force b = -div sigma = -a (2 lambda + 4 mu, 2 lambda + 5 mu) of
# <Body force/Function> (weighted by 1 - beta on the FE region, beta on the particles). Prints
# a Markdown table of the displacement error at the FE nodes and particles, the force residual
# of the exact field (ghost force) relative to the FE force scale, and the applied load (exact
# b_x times the volume: -4500 N for PMB) as the model, the FE degree, the overlap width W, the
# particle spacing dx and the FE cell size h change.
# usage: bash doc/benchmarks/coupling_patch/linear_strain_study.sh [path/to/perideal-solid]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
solver="${1:-$here/../../../build/bin/perideal-solid}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
field='1e-3*(x^2 + x*y); 1e-3*(2*x^2 + y^2)/2'
echo "| model | FE | W [mm] | dx [mm] | h [mm] | error FE nodes | error particles | ghost force / FE force scale | applied load x [N] |"
echo "|---|---|---|---|---|---|---|---|---|"
run() { # model degree W dx ncells
  /usr/bin/python3 - "$here" "$work/p.prm" "$field" "$@" <<'PY'
import sys
here, dst, field, model, degree, W, dx, n = sys.argv[1:]
sys.path.insert(0, here + "/../../../contrib")
import prm_fill
fields = {
    "BOUNDARY_CONDITIONS": "\n".join([
        "    set Names = boundary", "    subsection boundary",
        "      set Boundary ids = 0, 1, 2, 3", f"      set Function     = {field}", "    end"]),
    "EXACT": field, "DEGREE": degree, "DX": dx,
    "GENERATOR_ARGUMENTS": f"{n}, {n} : 0, 0 : 0.1, 0.1 : true",
    "BLENDING": f"min(1, max(0, min(min((x - 0.03) / {W}, (0.07 - x) / {W}), "
                f"min((y - 0.03) / {W}, (0.07 - y) / {W}))))"}
if model == "PMB":
    # plane stress, nu = 1/3: lambda* = mu = 75 GPa
    fields["BODY_FORCE"] = "-1e-3*(2*75e9 + 4*75e9); -1e-3*(2*75e9 + 5*75e9)"
else:
    # plane stress, nu = 0.3: lambda* = E nu / (1 - nu^2), mu = E / (2 (1 + nu))
    fields["BODY_FORCE"] = ("-1e-3*(2*200e9*0.3/0.91 + 4*200e9/2.6); "
                            "-1e-3*(2*200e9*0.3/0.91 + 5*200e9/2.6)")
    fields["MATERIAL"] = "\n".join([
        "  set Model   = linear peridynamic solid", "  subsection linear peridynamic solid",
        "    set Young's modulus = 200e9", "    set Poisson's ratio = 0.3", "  end"])
    fields["POISSON_RATIO"] = "0.3"
prm_fill.fill(here + "/static.prm", fields, dst)
PY
  out=$(cd "$work" && "$solver" p.prm)
  errors=$(echo "$out" | sed -n 's/.*FE nodes \([^,]*\), particles \(.*\)/\1 | \2/p')
  ghost=$(echo "$out" | sed -n 's/^Force residual of the exact field.*scale: \(.*\)/\1/p')
  applied=$(echo "$out" | sed -n 's/^Applied load: \([^ ]*\) .*/\1/p')
  echo "| $1 | Q$2 | $(/usr/bin/python3 -c "print(f'{$3*1e3:g}')") | $(/usr/bin/python3 -c "print(f'{$4*1e3:g}')") | $(/usr/bin/python3 -c "print(f'{100/$5:g}')") | $errors | $ghost | $applied |"
}
for model in PMB LPS; do
  for degree in 1 2; do
    for W in 0.005 0.01 0.02; do run $model $degree $W 1e-3 25; done
    run $model $degree 0.01 5e-4 25
    run $model $degree 0.01 1e-3 50
    run $model $degree 0.01 5e-4 50
  done
done
