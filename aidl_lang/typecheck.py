"""Static checks (placeholder, filled below)."""
def check(program, sink):
    pass
