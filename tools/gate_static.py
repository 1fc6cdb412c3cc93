#!/usr/bin/python3
"""The Antoci et al. (2007) gate at rest under still water of level H on its upstream face (docs/coupling.md,
section 14): the free end's displacement of a clamped inextensible Euler-Bernoulli beam under hydrostatic
follower pressure, with small rotations (closed form: q0 L^4 / 8EI + 11 dq L^4 / 120EI) and large ones (the
shape found by fixed-point iteration on the rotation). The quasi-static reference for the gate's late phase.
    tools/gate_static.py
"""
import numpy as np
def tip(H, Ep, L=0.079, t=0.005, clamp_y=0.08, rho=1000.0, g=9.81, N=800, nonlinear=True):
    """Free end's (x, rise) for water level H [m] and bending modulus Ep [Pa] (E plane stress, E/(1-nu^2) plane strain)."""
    EI = Ep * t**3 / 12.0
    s = np.linspace(0, L, N + 1); ds = s[1] - s[0]
    th = np.zeros(N + 1)
    for it in range(2000):
        tx, ty = np.sin(th), -np.cos(th)
        x = np.concatenate([[0], np.cumsum(0.5 * (tx[1:] + tx[:-1]) * ds)])
        y = clamp_y + np.concatenate([[0], np.cumsum(0.5 * (ty[1:] + ty[:-1]) * ds)])
        if not nonlinear: x, y = 0 * s, clamp_y - s; tx, ty = 0 * s, -np.ones_like(s)
        p = rho * g * np.clip(H - y, 0, None)
        fx, fy = p * np.cos(th if nonlinear else 0 * th), p * np.sin(th if nonlinear else 0 * th)
        # moment at s of the loads beyond s: M(s) = int_s^L (r(s') - r(s)) x f(s') ds'
        M = np.zeros(N + 1)
        for k in range(N + 1):
            w = np.ones(N + 1 - k); w[0] = w[-1] = 0.5
            dx_, dy_ = x[k:] - x[k], y[k:] - y[k]
            M[k] = np.sum(w * (dx_ * fy[k:] - dy_ * fx[k:])) * ds
        kappa = M / EI  # curvature: a positive moment turns the beam towards +x as it goes down
        new = np.concatenate([[0], np.cumsum(0.5 * (kappa[1:] + kappa[:-1]) * ds)])
        if np.max(np.abs(new - th)) < 1e-12: break
        th = 0.7 * th + 0.3 * new
    if not nonlinear:  # small rotations: x' = theta
        return np.sum(0.5 * (th[1:] + th[:-1]) * ds), 0.0
    tx, ty = np.sin(th), -np.cos(th)
    x = np.concatenate([[0], np.cumsum(0.5 * (tx[1:] + tx[:-1]) * ds)])
    y = clamp_y + np.concatenate([[0], np.cumsum(0.5 * (ty[1:] + ty[:-1]) * ds)])
    return x[-1], y[-1] - (clamp_y - L)
E, nu = 10e6, 0.4  # the scene's rubber
for H in [0.105, 0.109, 0.113, 0.122]:
    for name, Ep in [('plane strain', E / (1 - nu**2)), ('plane stress', E)]:
        lx, _ = tip(H, Ep, nonlinear=False); ux, uy = tip(H, Ep)
        print('H %.3f %s: linear %.1f mm, large deflection x %.1f mm, y %.1f mm' % (H, name, 1e3 * lx, 1e3 * ux, 1e3 * uy))
