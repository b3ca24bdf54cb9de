# Plant label stake: a 50 x 25 mm head with 3 mm rounded corners, the word "BASIL"
# engraved 8 mm tall in it; below it a 12 mm wide stake 80 mm long, ending in a
# pointed tip 15 mm long (so 120 mm overall).
param head_w = 50 mm, min = 40 mm, max = 80 mm
param stake_w = 12 mm, min = 8 mm, max = 16 mm
thickness 3 mm

solid label {
    head = RoundedRectangle(center=(0, 50), width=head_w, height=25, corner_radius=3)
    stake = Rectangle(center=(0, 0), width=stake_w, height=80)
    tip = Triangle(center=(0, -50), base=stake_w, height=15, rotation=180)
    Below(stake, head)
    AlignCenterX(stake, head)
    Below(tip, stake)
    AlignCenterX(tip, stake)
    drawing word {
        t = Text("BASIL", (0, 50), size=8, valign="middle")
    }
    At(word.t.position, head.center)
    assert self.bb.height == 120 mm, "120 mm overall"
    assert tip.bb.height == 15 mm, "tip 15 mm"
    Fixed(head)
}
