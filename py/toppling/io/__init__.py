"""Output and input of a run: summary.json, PNG plots, ParaView series, and reading a run folder back."""
