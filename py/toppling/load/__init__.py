"""Loading a scene: tilting (gravity rotated, ramps, stages judged to equilibrium or failure)."""
