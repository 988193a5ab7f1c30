#!/usr/bin/env bash
# Remakes docs/head_on_agent.gif (README, "Watch an episode"): a trained policy on the head-on
# scenario file, evaluated with --replay; its actions, read back from the replay page, replayed
# by `simulate --gif` (the same steps: simulate widens the policy's float actions to double as
# evaluate does).
#
# usage: scripts/make_head_on_gif.sh POLICY.pt [WORK_DIR]
set -euo pipefail
policy=$1
work=${2:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/bin
scenario=$root/configs/scenarios/head-on.yaml

"$bin/evaluate" --policy "$policy" --name agent --scenario "$scenario" --replay --out "$work/eval" >/dev/null
/usr/bin/python3 - "$work/eval/replays/head-on.html" "$work/actions.csv" <<'PY'
import base64, json, re, struct, sys
page = open(sys.argv[1], encoding="utf-8").read()
data = json.loads(re.search(r'id="replay-data">(.*?)</script>', page, re.S).group(1))
fields = data["step_fields"]
run = data["runs"][0]
numbers = struct.unpack(f"<{len(fields) * run['steps']}f", base64.b64decode(run["numbers"]))
thrust, moment = fields.index("thrust_action"), fields.index("moment_action")
with open(sys.argv[2], "w") as out:
    out.write("a0,a1\n")
    for k in range(1, run["steps"]):  # step 0 is the reset
        row = numbers[k * len(fields) : (k + 1) * len(fields)]
        out.write(f"{row[thrust]!r},{row[moment]!r}\n")
PY
"$bin/simulate" --scenario "$scenario" --actions "$work/actions.csv" --set env.test_mode=true \
  --out "$work/trace.csv" --gif "$root/docs/head_on_agent.gif" --frame-stride 8
echo "wrote $root/docs/head_on_agent.gif ($(stat -c %s "$root/docs/head_on_agent.gif") bytes)"
