#!/usr/bin/env bash
# Writes the schema-version-1 results databases that
# tests/results/test_results_migration.cpp migrates: four comparisons of the
# mould (serials SN-1, SN-2, SN-3, then SN-2 measured again) stored by
# `furrow compare --db` of a furrow whose results schema is version 1
# (0.1.0, commit cb5aa9a), into
#   results.sqlite   the SQLite file itself (checkpointed, no -wal file), and
#   results.pg.sql   pg_dump's script of the same parts in PostgreSQL.
# They are kept as that furrow wrote them: do not regenerate them with a
# later furrow, which would write a later schema.
#
#   bash tests/results/schema_v1/make_fixtures.sh /path/to/furrow-of-schema-1
#
# Needs Debian's postgresql (initdb, pg_ctl, pg_dump); as root the server
# runs as the user postgres.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
furrow=$(realpath "${1:?usage: make_fixtures.sh FURROW_OF_SCHEMA_VERSION_1}")
work=$(mktemp -d /tmp/furrow-schema-v1-XXXXXX)
chmod 755 "$work"
part=$root/examples/parts/mould.json
# A verdict (0 pass, 1 fail, 4 inconclusive) is fine; bad input or a failed computation is not.
verdict() { "$@" > /dev/null || { local rc=$?; [ $rc -eq 1 ] || [ $rc -eq 4 ]; }; }

"$furrow" partition "$part" --out "$work/regions.json" --grid 40x40 > /dev/null
verdict "$furrow" plan "$part" --regions "$work/regions.json" --points 30 --out "$work/plan"
for seed in 1 2 3 4; do
  "$furrow" simulate-measurement "$part" --plan "$work/plan/plan.json" --out "$work/m$seed.csv" --seed "$seed" > /dev/null
done

store_all() {  # $1: the --db location
  local serials=(SN-1 SN-2 SN-3 SN-2) k
  for k in 0 1 2 3; do
    verdict "$furrow" compare "$part" --measurements "$work/m$((k + 1)).csv" --plan "$work/plan/plan.json" \
      --out "$work/c$k.json" --db "$1" --serial "${serials[$k]}"
  done
}

store_all "$work/results.sqlite"
cp "$work/results.sqlite" "$here/results.sqlite"

bin=$(ls -d /usr/lib/postgresql/*/bin | sort -V | tail -1)
as_server() { if [ "$(id -u)" = 0 ]; then chown -R postgres "$work"; runuser -u postgres -- "$@"; else "$@"; fi; }
as_server "$bin/initdb" -D "$work/data" -U furrow_admin --auth=trust -E UTF8 --locale=C -N > /dev/null
port=$((20000 + RANDOM % 20000))
as_server "$bin/pg_ctl" -D "$work/data" -l "$work/server.log" -w -o "-p $port -k $work -c listen_addresses=''" start > /dev/null
trap 'as_server "$bin/pg_ctl" -D "$work/data" -m immediate stop > /dev/null; rm -rf "$work"' EXIT
"$bin/createdb" -h "$work" -p "$port" -U furrow_admin results
store_all "postgresql://furrow_admin@/results?host=$work&port=$port"
"$bin/pg_dump" -h "$work" -p "$port" -U furrow_admin --no-owner --no-privileges results > "$here/results.pg.sql"
echo "wrote $here/results.sqlite and $here/results.pg.sql"
