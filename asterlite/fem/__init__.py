"""Structural front end: DOF sets, discrete elements, frames, assembly and constraints."""
