# A rectangular plate 120.65 x 80.26 mm, 6.35 mm thick, with four 5.5 mm holes whose
# centres are 10.0 mm in from the long sides and 8.0 mm in from the short sides.

param W = 120.65 mm     # long sides along x
param H = 80.26 mm
param hole_d = 5.5 mm
param from_long = 10.0 mm    # centre to a long side (top / bottom)
param from_short = 8.0 mm    # centre to a short side (left / right)

thickness 6.35 mm

solid plate {
    body = Rectangle(center=(0, 0), width=W, height=H)
    Fixed(body)
    # the hole centres lie on the corners of this construction rectangle
    centres = Rectangle(center=(0, 0), width=W - 2 * from_short, height=H - 2 * from_long,
                        construction=true)
    CenterInside(centres, body)
    hole h {
        c = Circle(center=(0, 0), diameter=hole_d)
    }
    holes = CornerPattern(h, centres)
}
