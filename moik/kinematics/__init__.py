"""Kinematics helpers: orientation conventions and metrics, Jacobians."""
