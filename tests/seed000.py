"""Seed 000's own ``six_bar`` subroutine, transcribed line by line from the seed.

It solves velocity and acceleration as 4×4 linear systems per crank angle;
core uses closed-form derivatives, so agreement is an independent check. The
seed's frame is mirrored against ours: lever pivot at the origin, crank centre
at (0, l6), crank angle θ1 from +x counter-clockwise, cutting toward −x.
"""
import numpy as np

L1, L3, L4, L6, L61 = 0.125, 0.600, 0.150, 0.275, 0.575  # m


def six_bar(theta1, omega1=1.0, alpha1=0.0):
    s3 = np.sqrt((L1 * np.cos(theta1)) ** 2 + (L6 + L1 * np.sin(theta1)) ** 2)
    theta3 = np.arccos(L1 * np.cos(theta1) / s3)
    theta4 = np.pi - np.arcsin((L61 - L3 * np.sin(theta3)) / L4)
    sE = L3 * np.cos(theta3) + L4 * np.cos(theta4)
    A = np.array([[np.sin(theta3), s3 * np.cos(theta3), 0, 0],
                  [-np.cos(theta3), s3 * np.sin(theta3), 0, 0],
                  [0, L3 * np.sin(theta3), L4 * np.sin(theta4), 1],
                  [0, L3 * np.cos(theta3), L4 * np.cos(theta4), 0]])
    B = np.array([L1 * np.cos(theta1), L1 * np.sin(theta1), 0, 0])
    omega = np.linalg.solve(A, omega1 * B)
    v2, omega3, omega4, vE = omega
    A = np.array([[np.sin(theta3), s3 * np.cos(theta3), 0, 0],
                  [np.cos(theta3), -s3 * np.sin(theta3), 0, 0],
                  [0, L3 * np.sin(theta3), L4 * np.sin(theta4), 1],
                  [0, L3 * np.cos(theta3), L4 * np.cos(theta4), 0]])
    At = np.array([[omega3 * np.cos(theta3), v2 * np.cos(theta3) - s3 * omega3 * np.sin(theta3), 0, 0],
                   [-omega3 * np.sin(theta3), -v2 * np.sin(theta3) - s3 * omega3 * np.cos(theta3), 0, 0],
                   [0, L3 * omega3 * np.cos(theta3), L4 * omega4 * np.cos(theta4), 0],
                   [0, -L3 * omega3 * np.sin(theta3), -L4 * omega4 * np.sin(theta4), 0]])
    Bt = np.array([-L1 * omega1 * np.sin(theta1), -L1 * omega1 * np.cos(theta1), 0, 0])
    alpha = np.linalg.solve(A, -At @ omega + omega1 * Bt)
    a2, alpha3, alpha4, aE = alpha
    return dict(s3=s3, theta3=theta3, theta4=theta4, sE=sE, v2=v2, omega3=omega3,
                omega4=omega4, vE=vE, a2=a2, alpha3=alpha3, alpha4=alpha4, aE=aE)
