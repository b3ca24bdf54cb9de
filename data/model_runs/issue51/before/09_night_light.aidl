# Night-light front panel 150 x 150 mm: a square frame with a large round
# opening, a crescent moon (solid) inside the opening joined to the frame,
# and five small star cut-outs in the frame.

param size = 150 mm
param opening_d = 110 mm
param star_r = 6 mm

solid panel {
    solid frame {
        body = Rectangle(center=(0, 0), width=size, height=size)
        hole opening {
            window = Circle(center=(0, 0), diameter=opening_d)
        }
        CenterInside(opening, body)

        # five stars: one in each corner, one above the opening
        hole stars {
            s1 = Star(center=(-57, 57), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
            s2 = Star(center=(57, 57), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
            s3 = Star(center=(-57, -57), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
            s4 = Star(center=(57, -57), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
            s5 = Star(center=(0, 65), points=5, outer_radius=star_r, inner_radius=star_r * 0.45)
        }
        Rigid(stars.s1, stars.s2, stars.s3, stars.s4, stars.s5)
        CenterInside(stars, body)
        Fixed(body)
    }

    # the crescent: a disc with a bite taken out; its back overlaps the
    # frame on the left so it is held by the frame
    solid moon {
        disc = Circle(center=(-20, 0), radius=38)
        hole bite {
            b = Circle(center=(-6, 6), radius=34)
        }
    }
    # the moon's back reaches 3 mm into the frame
    moon.disc.left.x == frame.opening.window.left.x - 3 mm
    AlignCenterY(moon.disc, frame.opening)
    # the bite is offset up and right from the disc's center
    At(moon.bite.b.center, moon.disc.center, dx=14, dy=6)
}
