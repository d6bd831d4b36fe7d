"""Files: what core reads from and writes to disk, formatting results, never computing them.

``design_file`` reading design files defensively; ``io`` the curves CSV and the design
JSON; ``dynamics_io`` the dynamics CSV and JSON; ``atomic`` safe writes (the old file or
the new, never half); ``numtext`` numbers as CSV text, a whole array at once.
"""
