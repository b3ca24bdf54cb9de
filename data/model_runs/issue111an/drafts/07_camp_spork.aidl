# Request (camping): a flat-pack camping spork, 3 mm food-safe acrylic, 160 mm long.
# An oval bowl 40 x 56 mm (rx 20, ry 28) at the top, three tines made by two 2 mm
# wide slits 16 mm long running down from the bowl's top; a 14 mm wide handle 110 mm
# long below the bowl, its end rounded, with a 5 mm hanging hole 7 mm from the end;
# the owner's name "TOM" engraved 5 mm tall along the handle.
thickness 3 mm
kerf 0.15 mm

solid spork {
    bowl = Ellipse(center=(0, 132), rx=20, ry=28)
    handle = Slot(start=(0, 7), end=(0, 110), width=14)
    hole slits {
        s1 = Rectangle(center=(-6, 152), width=2, height=16)
        s2 = Rectangle(center=(6, 152), width=2, height=16)
    }
    hole hang { c = Circle(center=(0, 7), diameter=5) }
    drawing name { t = Text("TOM", position=(0, 60), size=5, rotation=90, valign="middle") }
    assert self.bb.height == 160 mm, "160 mm long"
    assert bowl.bb.width == 40 mm, "bowl 40 wide"
}
