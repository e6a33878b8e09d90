"""Transient dynamics on a modal basis: shock/friction forces, schemes, compiled loop."""
