"""The reference of the oblique-impact study (run.py) and of tests/decks/test_smooth_ball.py:
a ball on a plane integrated as LIGGGHTS's hooke/stiffness wall contact with tangential history
and nve/sphere's velocity Verlet. Standard library only."""

# The study's time step, steps and starting gap outside the layers (run.py's DT, STEPS, GAP).
DT, STEPS, GAP = 1e-6, 400, 1e-6


def ideal_ball(m, inertia, r, kn, kt, mu, vn, vt, dt=DT, steps=STEPS, gap=GAP):
    """A ball of mass m, moment of inertia `inertia`, radius r (lever r - overlap / 2, as
    LIGGGHTS's wall contact, surface_model_default.h) on the plane z = 0: LIGGGHTS's
    hooke/stiffness normal force kn overlap (gamman 0), tangential_model_history.h (shear += v_t
    dt, Ft = -kt shear, capped at mu Fn by rescaling the shear), nve/sphere's velocity Verlet,
    starting at z = r + gap. Returns (vx, vz, omega_y) after `steps` steps."""
    z, vx, vz, wy = r + gap, vt, -vn, 0.0
    fx = fz = ty = 0.0
    shear = 0.0
    h = 0.5 * dt
    for _ in range(steps):
        vx += h * fx / m
        vz += h * fz / m
        wy += h * ty / inertia
        z += dt * vz
        delta = r - z
        if delta > 0:
            fn = kn * delta
            lever = r - 0.5 * delta
            shear += (vx - lever * wy) * dt
            ft = -kt * shear
            if abs(ft) > mu * fn:
                ft *= mu * fn / abs(ft)
                shear = -ft / kt
            fx, fz, ty = ft, fn, -lever * ft
        else:
            fx = fz = ty = 0.0
            shear = 0.0
        vx += h * fx / m
        vz += h * fz / m
        wy += h * ty / inertia
    return vx, vz, wy
