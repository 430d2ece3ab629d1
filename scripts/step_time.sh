# Sourced by .ci/run, scripts/test.sh and scripts/ci_sanitizers.sh (from the repository root):
#   t=$(date +%s); ...; step "what ran" "$t"   prints "== what ran: N s" (CI watches its budget with them).
step() { echo "== $1: $(( $(date +%s) - $2 )) s"; }
