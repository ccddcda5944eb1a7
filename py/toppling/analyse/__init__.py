"""Analysing a run: failure points and surfaces, phi, zones, S/H and T/H, statistics over runs (numpy only)."""
