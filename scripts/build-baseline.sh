#!/bin/sh
# Build an earlier commit of mdr-impact (default dcd8fc3, the last `fast` that answered from one
# unverified solve) into DIR (default target/baseline-COMMIT) and print the binary's path, for
# `mdr-impact bench --baseline-bin PATH`. The commit is exported with `git archive`, so the
# working tree and the repository's worktrees are not touched.
# The default DIR lies inside this repository, so its .cargo/config.toml (the target CPU) applies
# to that build as to today's: the bench compares builds for the same CPU.
set -eu
commit="${1:-dcd8fc3}"
root="$(git rev-parse --show-toplevel)"
dir="${2:-$root/target/baseline-$commit}"
if [ ! -x "$dir/target/release/mdr-impact" ]; then
    mkdir -p "$dir"
    git -C "$root" archive "$commit" | tar -x -C "$dir"
    (cd "$dir" && cargo build --release --quiet >&2)
fi
echo "$dir/target/release/mdr-impact"
