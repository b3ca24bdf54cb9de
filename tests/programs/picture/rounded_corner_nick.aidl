# A bracket whose arm is joined flush with the top of a rounded body: the
# rounded corner leaves a nick between the arc and the arm's edge (issue 84).
# It is a notch narrower than the tool (W0519), not a neck: the material
# there is 6 mm wide.
solid bracket {
    body = RoundedRectangle(center=(0, 0), width=40, height=30, corner_radius=5)
    arm = Rectangle(center=(30, 12), width=20, height=6)
}
