"""Parametrised scenes: the tilting table, a block on an incline, a compression specimen."""
