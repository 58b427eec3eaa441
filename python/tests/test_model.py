"""Models: loading with overrides, inspection, transformations, and the functions of one state."""
import numpy as np
import pytest

import inerta
from conftest import SRC, model


def test_inspection_matches_cli_check(cli, hsx):
    out = cli("check", model("hsx.yaml")).stdout
    assert f"bodies ({len(hsx.bodies)})" in out and f"coordinates: {hsx.n_coords}" in out
    assert f"joints ({len(hsx.joints)}), constraint equations: {hsx.n_constraints}" in out
    assert "force elements (6): " + " ".join(f.name for f in hsx.forces) in out
    assert "outputs (6): " + " ".join(hsx.output_names) in out
    c = hsx.check()
    assert f"degrees of freedom: {c.dof}" in out
    assert c.redundant == hsx.n_constraints - c.rank and c.assembly.residual < 1e-9
    assert hsx.name == "hsx" and hsx.source.endswith("hsx.yaml") and hsx.dimension == 2
    assert hsx.is_pantograph and hsx.has_rig
    assert hsx.markers[hsx.contact_marker].name == "head.cm" and hsx.joints[hsx.rig_joint].name == "contact"
    head = hsx.bodies[hsx.find_body("head")]
    assert head.name == "head" and head.mass > 0 and head.q0.shape == (3,)
    assert hsx.find_body("ground") == -1 and hsx.find_body("nope") == -2
    assert hsx.find_joint("contact") == hsx.rig_joint and hsx.find_force("actuator") == 5
    act = hsx.forces[5]
    assert act.type == "actuator" and act.actuator["constant_force"] == -5374 and act.actuator["piston_mass"] == 3.45
    assert str(act.network) in ("k-c", "c-k") and act.n_states == 1 and act.body_i == hsx.find_body("base")
    assert hsx.forces[0].type == "gravity" and hsx.forces[0].body_i is None
    assert hsx.outputs[0].kind == inerta.OutputKind.reaction and hsx.outputs[1].needs_accelerations
    assert hsx.joints[0].type in list(inerta.JointType.__members__.values())
    assert len(hsx.coordinate_names) == hsx.n_coords and hsx.coord_name(4) == hsx.coordinate_names[4]
    assert hsx.body_name(-1) == "ground" and hsx.options.gravity and hsx.options.centripetal
    assert hsx.q0().shape == (hsx.n_coords,) and "dof" in repr(hsx)


def test_twobar_elements(twobar):
    assert [f.type for f in twobar.forces] == ["rotational_spring_damper", "spring", "damper", "inerter",
                                               "point_force"]
    k = twobar.forces[1]
    x, _ = inerta.assemble(twobar)
    assert k.free_length == pytest.approx(k.length(twobar, x))  # 'initial': the assembled distance
    assert twobar.dof == 2 and twobar.check().dof == 2 and not twobar.is_pantograph
    assert inerta.check_model(twobar).rank == 4


def test_overrides_are_applied(twobar):
    m = inerta.load_model(model("twobar.yaml"), {"k.k": 300, "b.b": 0})
    assert m.value("k.k") == 300 and m.value("b.b") == 0 and twobar.value("k.k") == 100
    assert m.overrides == ["k.k=300", "b.b=0"]
    assert inerta.load_model(model("twobar.yaml"), ["k.k=300", "b.b=0"]).overrides == m.overrides
    assert inerta.load_model(model("twobar.yaml"), "k.k=300").value("k.k") == 300
    r0 = inerta.simulate(twobar, 5)
    r1 = inerta.simulate(m, 5)
    assert abs(r0["C_y"][-1] - r1["C_y"][-1]) > 1e-4
    # the same as the file edited by hand
    text = (SRC / "models" / "twobar.yaml").read_text()
    edited = text.replace("k: 100, free_length", "k: 300, free_length").replace("b: 10}", "b: 0}")
    r2 = inerta.simulate(inerta.parse_model(edited, "edited.yaml"), 5)
    np.testing.assert_array_equal(r1["C_y"], r2["C_y"])
    # a key given again replaces its value; transformations are replayed after the reload
    m2 = m.with_options(centripetal=False).with_overrides({"k.k": 200})
    assert m2.overrides == ["k.k=200", "b.b=0"] and not m2.options.centripetal
    assert m2.history == ["options: centripetal=False"]
    assert inerta.model_value(text, "twobar.yaml", "c.c") == 100


def test_pantograph_loading(tmp_path, hsx):
    assert inerta.load_pantograph(model("hsx.yaml")).is_pantograph
    with pytest.raises(inerta.ModelError, match="no 'pantograph: {contact: <marker>}' section"):
        inerta.load_pantograph(model("twobar.yaml"))
    p = inerta.parse_model((SRC / "models" / "hsx.yaml").read_text(), "h.yaml", {"head.mass": 5.5})
    assert p.bodies[p.find_body("head")].mass == 5.5 and p.source == "h.yaml"


def test_transformations(hsx):
    s = hsx.with_suspension("k", {"k": 9e4})
    assert str(s.forces[5].network) == "k" and s.forces[5].network.value == 9e4 and s.n_states == 0
    s2 = inerta.with_suspension(hsx, inerta.resolve("k-(b|c)", {"k": 1e5, "b": 50, "c": 1e4}))
    assert s2.n_states == s2.forces[5].n_states == 2 and hsx.n_states == 1
    free, F = hsx.release_head()
    assert F == pytest.approx(70.02, abs=0.01) and not free.has_rig and free.is_pantograph
    assert free.find_joint("contact") < 0 and len(free.joints) == len(hsx.joints) - 1
    f2, F2 = inerta.release_head(hsx)
    assert F2 == F
    w = hsx.without_joint("contact")
    assert not w.has_rig and "F_contact" not in w.output_names
    with pytest.raises(inerta.InvalidArgument):
        hsx.without_joint("nope")
    with pytest.raises(inerta.ModelError):
        inerta.load_model(model("twobar.yaml")).with_suspension("k", {"k": 1})  # no actuator
    with pytest.raises(inerta.ModelError, match="no actuator"):
        inerta.suspension_index(inerta.load_model(model("twobar.yaml")))
    i = inerta.suspension_index(hsx)
    assert hsx.forces[i].type == "actuator"
    built = inerta.modal_analysis(hsx).model
    with pytest.raises(inerta.ModelError, match="not read from a file"):
        built.with_overrides({"head.mass": 1})


def test_functions_of_a_state(twobar):
    x, rep = inerta.assemble(twobar)
    assert rep.residual < 1e-10 and x.q.shape == (6,) and x.z.shape == (0,)
    C, Ct, Cq, gamma = inerta.constraints(twobar, 0.0, x)
    assert np.abs(C).max() < 1e-10 and Cq.shape == (4, 6)
    M, Q = inerta.forces(twobar, 0.0, x)
    assert M.shape == (6, 6) and np.allclose(M, M.T)
    qdd, lam, zd = inerta.accelerations(twobar, 0.25, x)  # F_a = 8 N at t = 0.25 s
    assert np.allclose(Cq @ qdd, gamma - 2 * 5 * (Cq @ x.qd) - 25 * C, atol=1e-9)
    assert lam.shape == (4,)
    reaction = inerta.joint_reaction(twobar, "A", 0.25, x, lam)
    assert reaction.shape == (3,) and np.isfinite(reaction).all()
    assert inerta.kinetic_energy(twobar, x) == 0.0
    assert inerta.stored_energy(twobar, 0.0, x) == pytest.approx(0.0, abs=1e-12)
    assert inerta.element_power(twobar, 0.0, x) == 0.0
    assert inerta.evaluate_output(twobar, "C_y", 0.0, x) == pytest.approx(
        inerta.simulate(twobar, 0.1, 0.1)["C_y"][0], abs=1e-12)
    assert inerta.needs_accelerations(twobar.outputs[0]) is False
    k = twobar.forces[1]
    assert k.length(twobar, x) == pytest.approx(k.free_length) and k.energy(twobar, 0.0, x) == pytest.approx(0)
    assert twobar.forces[2].power(twobar, 0.0, x) == 0.0
    x.qd[:] = 0.1  # State arrays are views of the state's memory
    assert inerta.kinetic_energy(twobar, x) > 0
    with pytest.raises(inerta.NumericalError, match="initial velocities violate"):  # drifts off the joints
        inerta.integrate(twobar, x, 0.0, 1.0, 0.1, rtol=1e-8)
    x = inerta.consistent_velocities(twobar, x)
    y, st = inerta.integrate(twobar, x, 0.0, 1.0, 0.1, rtol=1e-8)
    assert st.steps > 0 and not np.allclose(y.q, x.q)
    e, erep = inerta.static_equilibrium(inerta.load_model(model("onedof.yaml")))
    assert erep.force_residual < 1e-6
    with pytest.raises(inerta.InvalidArgument, match="does not fit"):
        inerta.accelerations(twobar, 0.0, inerta.State([0.0], [0.0]))
    s = inerta.State(x.q, x.qd)
    assert np.array_equal(s.copy().q, x.q) and "6 coordinates" in repr(s)


def test_iso8608_road_classes_and_overrides_routing():
    # ISO 8608: G_d(n0) = 16e-6 m³ for class A, ×4 per class; G_d ∝ n^-2; white velocity PSD 4π² n0² G_d0 v.
    assert inerta.iso8608_gd0("A") == pytest.approx(16e-6) and inerta.iso8608_gd0("c") == pytest.approx(256e-6)
    assert inerta.iso8608_psd("B", 0.2) == pytest.approx(64e-6 / 4)
    assert inerta.iso8608_velocity_psd("C", 20) == pytest.approx(4 * np.pi**2 * 0.01 * 256e-6 * 20)
    assert inerta.iso8608_variance("C", 0.05, 2) == pytest.approx(256e-6 * 0.01 * (1 / 0.05 - 1 / 2))
    with pytest.raises(inerta.InvalidArgument, match="class"):
        inerta.iso8608_gd0("J")
    to_model, to_catenary = inerta.split_overrides(model("hsx.yaml"), ["head.mass=5", "catenary.kc0=5000"])
    assert list(to_model) == ["head.mass=5"] and list(to_catenary) == ["catenary.kc0=5000"]


def test_consistent_velocities_give_the_drive_its_speed():
    m = inerta.parse_model("""
options: {gravity: true}
ground: {markers: {P: [0, 0]}}
bodies:
  - {name: base, mass: 1, inertia: 0.1, position: [0, 0]}
  - {name: top, mass: 2, inertia: 0.1, position: [0, 1]}
joints:
  - {name: rail, type: prismatic, markers: [ground.P, base.cm], axis: [0, 1]}
  - {name: rail2, type: prismatic, markers: [ground.P, top.cm], axis: [0, 1]}
  - {name: drive, type: driving, body: base, coordinate: y, motion: {type: ramp, slope: 0.2}}
forces:
  - {name: k, type: spring, markers: [base.cm, top.cm], k: 2000, free_length: 1}
""")
    x, _ = inerta.static_equilibrium(m)
    assert np.all(x.qd == 0)
    y = inerta.consistent_velocities(m, x)
    assert y.qd[1] == pytest.approx(0.2) and y.qd[4] == pytest.approx(0.0, abs=1e-12)
    assert m.options.max_violation == pytest.approx(1e-4)
