"""Kinematics helpers: orientation conventions and metrics, SO(3) maths, Jacobians, trajectories."""
