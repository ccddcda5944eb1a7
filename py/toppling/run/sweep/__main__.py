"""``./toppling-sweep TABLE SCRIPT [--lines 3,5-8] [--scheduler tcp://host:port] [--workers N]``: the
lines of a yade-batch table run as Dask tasks, on a local cluster (127.0.0.1 only) or on the user's
scheduler; prints progress, then one table of the summaries. Exit status 1 if a line failed."""
import argparse
import os
import signal
import sys


def arguments(argv):
    parser = argparse.ArgumentParser(prog="toppling-sweep", description=__doc__.split(":", 1)[1].strip())
    parser.add_argument("table", help="a yade-batch table (the same files yade-batch reads)")
    parser.add_argument("script", help="the script each line runs (a line's !SCRIPT column overrides it)")
    parser.add_argument("--lines", help="lines to run, yade-batch's form: 3,5-8 (default: all)")
    parser.add_argument("--scheduler", help="a running Dask scheduler: its address (tcp://host:port, tls://...) "
                                            "or its --scheduler-file (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=os.cpu_count(),
                        help="workers of the local cluster, one thread each (default: the machine's cores, %(default)s)")
    parser.add_argument("--figures", help="comma-separated summary keys for the final table (default: the "
                                          "scalars every summary has, at most six)")
    parser.add_argument("--csv", help="also write every line's row (all scalar figures) to this CSV file")
    args = parser.parse_args(argv)
    if args.workers < 1:
        parser.error(f"--workers {args.workers}: give 1 or more")
    return args


def main(argv=None) -> int:
    args = arguments(argv)
    try:
        import distributed  # noqa: F401
    except ImportError:
        sys.exit("toppling-sweep needs Dask: run scripts/setup.sh (it installs Debian's python3-distributed)")
    from toppling.run.sweep import report, sweep
    try:
        planned = sweep.plan(args.table, args.script, args.lines)
    except ValueError as e:
        sys.exit(f"toppling-sweep: {e}")
    todo = sum(not p.finished for p in planned)
    print(f"sweep: {len(planned)} lines of {args.table}, {len(planned) - todo} finished already", flush=True)
    results = sweep.skipped(planned)
    if todo:
        # a batch system ends a job with SIGTERM: stop as on Ctrl-C, the local cluster (and its runs) with us
        signal.signal(signal.SIGTERM, signal.default_int_handler)
        try:
            client, cluster = sweep.connect(args.scheduler, args.workers)
        except (OSError, TimeoutError) as e:
            sys.exit(f"toppling-sweep: no Dask scheduler at --scheduler {args.scheduler} ({e}): start one "
                     "(docs/sweeps.md) or leave --scheduler out for a local cluster")
        try:
            results = sweep.execute(planned, client, echo=lambda s: print(s, flush=True))
        except KeyboardInterrupt:
            print("sweep: stopped; finished lines are kept: run the same command again to go on", flush=True)
            return 130
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    table = report.rows(planned, results)
    print(report.markdown(table, args.figures.split(",") if args.figures else None))
    if args.csv:
        report.write_csv(table, args.csv)
    return 1 if any(r["status"] == "failed" for r in table) else 0


if __name__ == "__main__":
    sys.exit(main())
