"""Every exception family of ``liftoff.errors``, raised by a real library call (never
constructed here) and pickled — as a Dask worker or a process pool sends it back: the class,
the message, the ``kind``, the ``field`` and, for ``NotConverged``, the ``.solution`` survive.
A panic inside the library (a bug) reaches Python as ``NumericalError``; since no input is known
to make the library panic, the binding has a test-only ``_liftoff._panic_for_tests``.

A Dask sweep whose failing cases fail on a worker: the not-converged, infeasible and too-large
cases are solved in the cluster's worker processes, become rows there (equal to a serial
sweep's) and, submitted alone, raise their exception in the client with its attributes."""

from __future__ import annotations

import json
import os
import pickle

import numpy as np
import pytest

import liftoff
from liftoff import _liftoff

SMALL = {
    "dimensionless": {"foundation": "winkler", "gamma": 0.25e-3, "delta": 0.002857, "mu": 1.0, "nu": 0.3},
    "load": [{"kind": "point", "x": 0.0, "y": 0.0, "force": 1.0}],
    "mesh": {"elements": [8, 8]},
}


def edited(**sections) -> dict:
    """SMALL with sections replaced (a deep copy)."""
    scene = json.loads(json.dumps(SMALL))
    for k, v in sections.items():
        scene[k] = v
    return scene


def not_converging() -> dict:
    # One penalty step cannot settle the contact set (ERRORS.md E22).
    return edited(solver={"method": "penalty", "max_iterations": 1, "penalty": 1e-5})


def infeasible() -> dict:
    # A net upward load on a tensionless soil (E19).
    scene = edited()
    scene["load"][0]["force"] = -1.0
    return scene


def too_large() -> dict:
    # The memory limit is the scene's, not the machine's: 1 KiB cannot hold even this mesh (E17).
    return edited(solver={"memory_limit_gib": 1e-6})


def numerical() -> str:
    # Δ = 5e-324: a shear rigidity that overflows (κ_s = 1/(μΔ)), so the plate's factorisation
    # fails (E27; tests/fuzz_regressions.rs has the same scene). A plate 1e8 times stiffer than
    # its bed no longer fails: its rigid part is split off (E25 is not reached by a scene).
    text = liftoff.example_text("paper-winkler")
    assert "delta = 0.002857" in text
    return text.replace("delta = 0.002857", "delta = 5e-324")


def assert_pickles(e: liftoff.LiftoffError) -> liftoff.LiftoffError:
    """The exception after a pickle round trip: same class, message, kind and field."""
    back = pickle.loads(pickle.dumps(e))
    assert type(back) is type(e), (type(back), type(e))
    assert str(back) == str(e) and back.message == e.message
    assert back.kind == e.kind and back.field == e.field
    return back


# (exception class, the Python builtin it also is, its kind, a call that raises it)
FAMILIES = [
    (liftoff.SceneError, ValueError, "invalid",
     lambda: liftoff.solve(edited(dimensionless={**SMALL["dimensionless"], "gamma": -1.0}))),
    (liftoff.TooLarge, MemoryError, "too-large", lambda: liftoff.solve(too_large())),
    (liftoff.Infeasible, liftoff.LiftoffError, "infeasible", lambda: liftoff.solve(infeasible(), method="qp")),
    (liftoff.NumericalError, ArithmeticError, "numerical", lambda: liftoff.solve(numerical())),
    (liftoff.LiftoffIOError, OSError, "io", lambda: liftoff.solve("no/such/scene.toml")),
    (liftoff.NotConverged, liftoff.LiftoffError, "not-converged", lambda: liftoff.solve(not_converging())),
]


@pytest.mark.parametrize("cls, builtin, kind, call", FAMILIES, ids=[f[2] for f in FAMILIES])
def test_every_exception_family_is_raised_and_pickles(cls, builtin, kind, call):
    with pytest.raises(cls) as info:
        call()
    e = info.value
    assert type(e) is cls, f"{kind}: raised {type(e).__name__}"
    assert isinstance(e, builtin) and isinstance(e, liftoff.LiftoffError), kind
    assert e.kind == kind, (kind, e.kind)
    assert str(e), f"{kind}: the library's message is carried"
    assert_pickles(e)


def test_the_scene_error_names_its_field_after_pickling():
    with pytest.raises(liftoff.SceneError) as e:
        liftoff.solve(edited(dimensionless={**SMALL["dimensionless"], "gamma": -1.0}))
    assert e.value.field == "dimensionless.gamma"
    assert assert_pickles(e.value).field == "dimensionless.gamma"


def test_the_messages_are_the_documented_ones():
    """The message of each family is the library's (docs/ERRORS.md), not a generic one."""
    for call, text in [
        (lambda: liftoff.solve(too_large()), "more than the 0.00 GiB allowed"),
        (lambda: liftoff.solve(infeasible(), method="qp"), "net load is upward"),
        (lambda: liftoff.solve(numerical()), "not positive definite"),
        (lambda: liftoff.solve(not_converging()), "still changing after 1 iterations"),
    ]:
        with pytest.raises(liftoff.LiftoffError, match=text):
            call()


def test_not_converged_carries_its_solution_through_pickle():
    with pytest.raises(liftoff.NotConverged) as info:
        liftoff.solve(not_converging())
    e = info.value
    s = e.solution
    assert s is not None and not s.converged and s.status.startswith("not converged")
    back = assert_pickles(e)
    t = back.solution
    assert type(t) is type(s) and not t.converged and t.status == s.status
    assert t.summary == s.summary and t.V_max == s.V_max
    for name in ("w", "sigma", "pressure", "gap", "mx"):
        assert np.array_equal(getattr(t, name), getattr(s, name)), name
    # The iterate is the library's, not a stand-in: one penalty step, as the summary says.
    assert s.summary["iterations"] == 1 and s.summary["converged"] is False


def test_a_failing_combination_raises_not_converged_whose_solution_pickles():
    text = liftoff.example_text("raft-combinations")
    cases = sorted({line.split('"')[1] for line in text.splitlines() if line.strip().startswith("case =")})
    text += '\n[[combination]]\nname = "pulled"\nfactors = { ' + ", ".join(f"{c} = -1.0" for c in cases) + " }\n"
    with pytest.raises(liftoff.NotConverged, match="pulled") as info:
        liftoff.solve(text)
    back = assert_pickles(info.value)
    c = back.solution
    assert c.missing == ["pulled"] and "pulled" in c.errors and c.envelope is None
    assert set(c.solutions) == set(info.value.solution.solutions)


def test_a_panic_in_the_library_is_a_numerical_error():
    """A bug that panics reaches Python as NumericalError (catchable by ``except Exception``),
    with the panic's message; the interpreter and the library keep working afterwards."""
    with pytest.raises(liftoff.NumericalError, match="deliberate test panic") as info:
        _liftoff._panic_for_tests("deliberate test panic")
    e = info.value
    assert e.kind == "numerical" and "internal error" in str(e)
    assert_pickles(e)
    assert liftoff.solve(SMALL).converged


# -- failing cases on a Dask worker ------------------------------------------------------------


@pytest.fixture(scope="module")
def client():
    # No importorskip: ./test installs dask[distributed] (conftest.py fails a skipped test).
    import distributed
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


def test_failing_cases_fail_on_a_dask_worker(client):
    failing = {"not-converged": not_converging(), "infeasible": infeasible(), "too-large": too_large()}
    scenes = [SMALL, *failing.values()]
    rows = liftoff.sweep(scenes, client=client)
    serial = liftoff.sweep(scenes, workers=1)
    assert rows == serial, "the cluster's rows are the serial sweep's"
    assert [r["ok"] for r in rows] == [True, False, False, False]
    assert [r["error_kind"] for r in rows] == [None, *failing], rows
    assert rows[0]["converged"] and rows[0]["V_max"] > 0
    # The not-converged row keeps the iterate's scalars; the others have only the error.
    assert rows[1]["converged"] is False and rows[1]["iterations"] == 1
    assert "net load is upward" in rows[2]["error"] and "GiB" in rows[3]["error"]

    # Submitted alone, each case raises on a worker (another process) and its exception comes
    # back to the client with its class and attributes.
    pids = set(client.run(os.getpid).values())
    assert os.getpid() not in pids, "the workers are processes of their own"
    classes = {"not-converged": liftoff.NotConverged, "infeasible": liftoff.Infeasible,
               "too-large": liftoff.TooLarge}
    for kind, scene in failing.items():
        future = client.submit(liftoff.solve, scene, pure=False)
        with pytest.raises(classes[kind]) as info:
            future.result()
        assert info.value.kind == kind
    # NotConverged brings the worker's iterate: the serial one, bit for bit (but its timings).
    with pytest.raises(liftoff.NotConverged) as remote:
        client.submit(liftoff.solve, not_converging(), pure=False).result()
    with pytest.raises(liftoff.NotConverged) as here:
        liftoff.solve(not_converging())
    a, b = remote.value.solution, here.value.solution
    assert a is not None and np.array_equal(a.sigma, b.sigma) and np.array_equal(a.w, b.w)
    timed = ("time_s", "method_time_s")
    assert {k: v for k, v in a.summary.items() if k not in timed} == \
        {k: v for k, v in b.summary.items() if k not in timed}
