"""K. M. Lynch, F. C. Park, *Modern Robotics: Mechanics, Planning, and Control*, Cambridge
University Press, 2017 (the freely available preprint of December 2019). Notation: plain
italic R, p, T; a unit axis with a hat (\\hat\\omega); [x] the so(3)/se(3) matrix of a vector
or twist; e^{...} the matrix exponential; calligraphic twists and wrenches; [Ad_T]."""

import numpy as np
from _num import I3, Ad, E, ad, col, ddt, expm, hat, rot, rotz

BOOK = {"key": "lynch-park", "title": "Lynch & Park, Modern Robotics",
        "edition": "1st ed., Cambridge UP 2017 (preprint Dec. 2019)"}

TABLE = r"""
R: rotation
\hat\omega: unit vector
\omega: vector
\theta: angle
p: vector
T: transform
T_1: transform
T_2: transform
\mathcal{V}: twist
\mathcal{V}_1: twist
\mathcal{V}_2: twist
\mathcal{F}: wrench
\mathcal{I}_1: scalar
\mathcal{I}_2: scalar
\mathcal{I}_3: scalar
"""


def _rod(v, sign=1, c=1):
    w = hat(v.hat_omega)
    return I3 + sign * np.sin(v.theta) * w + (c - np.cos(v.theta)) * w @ w


def _G(v):
    w, t = hat(v.hat_omega), v.theta
    return I3 * t + (1 - np.cos(t)) * w + (t - np.sin(t)) * w @ w


def _Ginv(v, half=0.5):
    w, t = hat(v.hat_omega), v.theta
    return I3 / t - half * w + (1 / t - 0.5 / np.tan(t / 2)) * w @ w


def _D(v):
    return np.diag([v.I_1, v.I_2, v.I_3])


ENTRIES = [
    E("3.2.1", "(3.19)", r"R^T R = I", True, lambda v: (v.R.T @ v.R, I3)),
    E("3.2.1", "(3.19)", r"\det R = 1", True, lambda v: (np.linalg.det(v.R), 1)),
    E("3.2.3.1", "(3.30)", r"[\omega] = -[\omega]^T", True,
      lambda v: (hat(v.omega), -hat(v.omega).T)),
    E("3.2.3.1", "(3.31)", r"R[\omega]R^T = [R\omega]", True,
      lambda v: (v.R @ hat(v.omega) @ v.R.T, hat(v.R @ v.omega))),
    E("3.2.3.1", "(3.31)", r"R^T[\omega]R = [R\omega]", False,
      lambda v: (v.R.T @ hat(v.omega) @ v.R, hat(v.R @ v.omega))),
    E("3.2.3.3", "(3.51)",
      r"e^{[\hat\omega]\theta} = I + \sin\theta\,[\hat\omega] + (1 - \cos\theta)[\hat\omega]^2",
      True, lambda v: (expm(hat(v.hat_omega) * v.theta), _rod(v))),
    E("3.2.3.3", "(3.51)",
      r"e^{[\hat\omega]\theta} = I - \sin\theta\,[\hat\omega] + (1 - \cos\theta)[\hat\omega]^2",
      False, lambda v: (expm(hat(v.hat_omega) * v.theta), _rod(v, sign=-1))),
    E("3.2.3.3", "(3.51)",
      r"e^{[\hat\omega]\theta} = I + \sin\theta\,[\hat\omega] + (1 + \cos\theta)[\hat\omega]^2",
      False, lambda v: (expm(hat(v.hat_omega) * v.theta),
                        I3 + np.sin(v.theta) * hat(v.hat_omega)
                        + (1 + np.cos(v.theta)) * hat(v.hat_omega) @ hat(v.hat_omega))),
    E("3.2.3.3", "(3.51)", r"e^{[\hat\omega]\theta}e^{-[\hat\omega]\theta} = I", True,
      lambda v: (expm(hat(v.hat_omega) * v.theta) @ expm(-hat(v.hat_omega) * v.theta), I3)),
    E("3.2.3.3", "(3.54)", r"\operatorname{tr} e^{[\hat\omega]\theta} = 1 + 2\cos\theta", True,
      lambda v: (np.trace(expm(hat(v.hat_omega) * v.theta)), 1 + 2 * np.cos(v.theta))),
    E("3.2.3.3", "(3.54)", r"\operatorname{tr} e^{[\hat\omega]\theta} = 1 + \cos\theta", False,
      lambda v: (np.trace(expm(hat(v.hat_omega) * v.theta)), 1 + np.cos(v.theta))),
    E("3.2.3.3", "(3.52)", r"e^{[\hat\omega]\theta}\hat\omega = \hat\omega", True,
      lambda v: (expm(hat(v.hat_omega) * v.theta) @ v.hat_omega, v.hat_omega)),
    E("3.2.3.3", "(3.51)",
      r"\frac{d}{d\theta}e^{[\hat\omega]\theta} = [\hat\omega]e^{[\hat\omega]\theta}", True,
      lambda v: ((expm(hat(v.hat_omega) * (v.theta + 1e-6))
                  - expm(hat(v.hat_omega) * (v.theta - 1e-6))) / 2e-6,
                 hat(v.hat_omega) @ expm(hat(v.hat_omega) * v.theta))),
    E("3.2.3.1", "(3.33)", r"\left\| R p \right\| = \left\| p \right\|", True,
      lambda v: (np.linalg.norm(v.R @ v.p), np.linalg.norm(v.p))),
    E("3.2.3.1", "(3.30)", r"\|[\omega] p\| = \|\omega \times p\|", True,
      lambda v: (np.linalg.norm(hat(v.omega) @ v.p),
                 np.linalg.norm(np.cross(v.omega.ravel(), v.p.ravel())))),
    E("3.3.2", "(3.85)", r"T[\mathcal{V}]T^{-1} = [\mathrm{Ad}_T\mathcal{V}]", True,
      lambda v: (v.T @ hat(v.V) @ np.linalg.inv(v.T), hat(Ad(v.T) @ v.V))),
    E("3.3.2", "(3.85)", r"T^{-1}[\mathcal{V}]T = [\mathrm{Ad}_T\mathcal{V}]", False,
      lambda v: (np.linalg.inv(v.T) @ hat(v.V) @ v.T, hat(Ad(v.T) @ v.V))),
    E("3.3.2", "Prop. 3.20",
      r"[\mathrm{Ad}_{T_1}][\mathrm{Ad}_{T_2}] = [\mathrm{Ad}_{T_1 T_2}]", True,
      lambda v: (Ad(v.T_1) @ Ad(v.T_2), Ad(v.T_1 @ v.T_2))),
    E("3.3.2", "Prop. 3.20", r"[\mathrm{Ad}_T]^{-1} = [\mathrm{Ad}_{T^{-1}}]", True,
      lambda v: (np.linalg.inv(Ad(v.T)), Ad(np.linalg.inv(v.T)))),
    E("3.3.2", "Prop. 3.20", r"[\mathrm{Ad}_T]^{-1} = [\mathrm{Ad}_T]^T", False,
      lambda v: (np.linalg.inv(Ad(v.T)), Ad(v.T).T)),
    E("3.4", "(3.98)",
      r"\mathcal{F}^T[\mathrm{Ad}_T]\mathcal{V} = ([\mathrm{Ad}_T]^T\mathcal{F})^T\mathcal{V}",
      True, lambda v: (v.F.T @ Ad(v.T) @ v.V, (Ad(v.T).T @ v.F).T @ v.V)),
    E("8.2.2", "(8.38)",
      r"[\mathrm{ad}_{\mathcal{V}_1}]\mathcal{V}_2 = -[\mathrm{ad}_{\mathcal{V}_2}]\mathcal{V}_1",
      True, lambda v: (ad(v.V_1) @ v.V_2, -ad(v.V_2) @ v.V_1)),
    E("8.2.2", "(8.38)",
      r"[\mathrm{ad}_{\mathcal{V}_1}]\mathcal{V}_2 = [\mathrm{ad}_{\mathcal{V}_2}]\mathcal{V}_1",
      False, lambda v: (ad(v.V_1) @ v.V_2, ad(v.V_2) @ v.V_1)),
    E("3.3.3.2", "(3.92)",
      r"\left(I\theta + (1 - \cos\theta)[\hat\omega] + (\theta - \sin\theta)[\hat\omega]^2\right)"
      r"\left(\frac{1}{\theta}I - \frac{1}{2}[\hat\omega] + \left(\frac{1}{\theta} - "
      r"\frac{1}{2}\cot\frac{\theta}{2}\right)[\hat\omega]^2\right) = I", True,
      lambda v: (_G(v) @ _Ginv(v), I3)),
    E("3.3.3.2", "(3.92)",
      r"\left(I\theta + (1 - \cos\theta)[\hat\omega] + (\theta - \sin\theta)[\hat\omega]^2\right)"
      r"\left(\frac{1}{\theta}I + \frac{1}{2}[\hat\omega] + \left(\frac{1}{\theta} - "
      r"\frac{1}{2}\cot\frac\theta2\right)[\hat\omega]^2\right) = I", False,
      lambda v: (_G(v) @ _Ginv(v, half=-0.5), I3)),
    E("8.2.1", "(8.27)",
      r"\left(R\operatorname{diag}(\mathcal{I}_1, \mathcal{I}_2, \mathcal{I}_3)R^T\right)^T"
      r" = R\operatorname{diag}(\mathcal{I}_1, \mathcal{I}_2, \mathcal{I}_3)R^T", True,
      lambda v: ((v.R @ _D(v) @ v.R.T).T, v.R @ _D(v) @ v.R.T)),
    E("3.2.1", "(3.19)", r"R^T R = I, \quad R \in SO(3)", True,
      lambda v: (v.R.T @ v.R, I3), note="a trailing declaration"),
    E("3.3.2", "Prop. 3.20",
      r"\left[\mathrm{Ad}_T\right]^{-1} = \left[\mathrm{Ad}_{T^{-1}}\right]", True,
      lambda v: (np.linalg.inv(Ad(v.T)), Ad(np.linalg.inv(v.T)))),
]

_ = (ad, col, ddt, rot, rotz)
