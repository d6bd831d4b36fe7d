"""The six-bar linkage: from what the user states to the measured cycle of the ram.

``spec`` the design as stated; ``designs`` and ``geometry`` synthesis and the rules (many
designs at once, one design); ``verdict`` why a design fails; ``kinematics`` closed-form
motion; ``rates`` the ram's higher φ-derivatives; ``polish`` and ``extrema`` bracketed
roots and exact peaks; ``metrics`` the measured cycle; ``margins`` how far a design clears
each rule; ``cut`` where the cutting force acts.
"""
