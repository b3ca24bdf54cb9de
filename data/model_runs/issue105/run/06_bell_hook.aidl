# Bicycle-bell hook (to hang a bike bell / helmet on the wall): a wall strip 24 mm wide
# x 70 mm tall with two 4.5 mm screw holes 12 mm from its ends, countersunk to 9 mm;
# at its bottom an arm 40 mm long x 10 mm tall sticking out to the right, ending in an
# upturned tip 10 mm wide x 22 mm tall (top 5 mm rounded), all one flat piece.
thickness 6 mm

solid hook {
    strip = RoundedRectangle(center=(0, 0), width=24, height=70, corner_radii=[4, 4, 0, 4])
    hole screws {
        top = Circle(center=(0, 23), diameter=4.5)
        bottom = Circle(center=(0, -23), diameter=4.5)
    }
    Countersink(screws, diameter=9)
    At(screws.top.center, strip.bb.top_left, dx=12, dy=-12)
    At(screws.bottom.center, strip.bb.bottom_left, dx=12, dy=12)

    arm = Rectangle(center=(32, -30), width=40, height=10)
    tip = RoundedRectangle(center=(57, -20), width=10, height=22,
                           corner_radii=[5, 5, 0, 0])
    # the arm leaves the strip's right side at the bottom
    RightOf(arm, strip)
    AlignBottom(arm, strip)
    # the tip stands on the arm's far end
    AlignRight(tip, arm)
    AlignBottom(tip, arm)
}
