"""A skipped test checks nothing: the suite fails when any test is skipped, so a missing
dependency (dask.distributed for the cluster tests) cannot turn into a silent pass."""


def pytest_sessionfinish(session, exitstatus):
    reporter = session.config.pluginmanager.get_plugin("terminalreporter")
    skipped = reporter.stats.get("skipped", []) if reporter else []
    if skipped:
        names = ", ".join(r.nodeid for r in skipped)
        print(f"\nerror: {len(skipped)} test(s) skipped; a skip fails this suite: {names}")
        session.exitstatus = 1
