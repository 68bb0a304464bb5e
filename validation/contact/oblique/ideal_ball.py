"""The reference of the oblique-impact studies (run.py, run_pairs.py) and of
tests/decks/test_smooth_ball.py: a ball on a plane integrated as LIGGGHTS's hooke/stiffness wall
contact with tangential history and nve/sphere's velocity Verlet, and two equal balls meeting
symmetrically as LIGGGHTS's pair gran does. Standard library only."""
import math

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


def ideal_pair(m, inertia, r, kn, kt, mu, vn, vt, dt=DT, steps=STEPS, gap=GAP):
    """Two equal balls (mass m, moment of inertia `inertia`, radius r) meeting head-on at
    relative normal speed vn and tangential speed vt, each moving at half of it, without spin,
    their surfaces `gap` apart: LIGGGHTS's pair gran hooke/stiffness with tangential history
    (pair_gran / tangential_model_history.h: relative velocity at the contact with the levers
    r - overlap / 2, shear += its tangential part dt, turned into the current tangent plane,
    Ft = -kt shear capped at mu Fn by rescaling the shear) and nve/sphere's velocity Verlet. The
    pair stays point-symmetric about the origin (ball 2 at -x1 with -v1 and the same spin), so
    ball 1 alone is integrated, in the plane of the motion. Returns ball 1's (tangential
    velocity, normal velocity away from ball 2, spin) after `steps` steps, along the initial
    tangential and normal directions: ball 1 starts at (-(r + gap / 2), 0) moving
    (vn / 2, vt / 2)."""
    x, y = -(r + 0.5 * gap), 0.0
    vx, vy, w = 0.5 * vn, 0.5 * vt, 0.0
    fx = fy = tz = 0.0
    sx = sy = 0.0  # shear displacement
    h = 0.5 * dt
    for _ in range(steps):
        vx += h * fx / m
        vy += h * fy / m
        w += h * tz / inertia
        x += dt * vx
        y += dt * vy
        dist = 2.0 * math.hypot(x, y)
        delta = 2.0 * r - dist
        if delta > 0:
            ex, ey = x * 2.0 / dist, y * 2.0 / dist  # en: from ball 2 towards ball 1
            cr = r - 0.5 * delta
            rvx, rvy = 2.0 * vx, 2.0 * vy  # v1 - v2
            vrn = rvx * ex + rvy * ey
            vtx, vty = rvx - vrn * ex, rvy - vrn * ey
            wr = 2.0 * cr * w  # cr1 w1 + cr2 w2 (about z)
            # vtr = vt - wr x en, wr along z: wr x en = (-wr ey, wr ex)
            vtx, vty = vtx + wr * ey, vty - wr * ex
            sx += vtx * dt
            sy += vty * dt
            s_n = sx * ex + sy * ey
            sx, sy = sx - s_n * ex, sy - s_n * ey
            fn = kn * delta
            ftx, fty = -kt * sx, -kt * sy
            ft = math.hypot(ftx, fty)
            if ft > mu * fn:
                ftx, fty = ftx * mu * fn / ft, fty * mu * fn / ft
                sx, sy = -ftx / kt, -fty / kt
            fx, fy = fn * ex + ftx, fn * ey + fty
            # torque on ball 1: its contact point lies at -cr en: (-cr en) x Ft
            tz = -cr * (ex * fty - ey * ftx)
        else:
            fx = fy = tz = 0.0
            sx = sy = 0.0
        vx += h * fx / m
        vy += h * fy / m
        w += h * tz / inertia
    return vy, -vx, w
