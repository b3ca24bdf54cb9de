# Night-light front panel, 150 x 150 mm: a square frame with a large round
# opening, a solid crescent moon inside the opening joined to the frame,
# and five small star cut-outs in the frame.

param size = 150 mm
param window_d = 100 mm
param star_r = 6 mm

solid panel {
    solid frame {
        body = Rectangle(center=(0, 0), width=size, height=size)
        Fixed(body)

        hole window {
            c = Circle(center=(0, 0), diameter=window_d)
        }
        CenterInside(window, body)

        # four stars in the corners and one above the opening
        hole stars {
            s1 = Star(center=(-55, 55), points=5, outer_radius=star_r, inner_radius=star_r * 0.4)
            s2 = Star(center=(55, 55), points=5, outer_radius=star_r, inner_radius=star_r * 0.4)
            s3 = Star(center=(-55, -55), points=5, outer_radius=star_r, inner_radius=star_r * 0.4)
            s4 = Star(center=(55, -55), points=5, outer_radius=star_r, inner_radius=star_r * 0.4)
            s5 = Star(center=(0, 63), points=5, outer_radius=star_r, inner_radius=star_r * 0.4)
        }
        Rigid(stars)
        CenterInside(stars, body)
    }

    # the crescent: a disc with a bite taken out; its back overlaps the
    # window's rim so it is held by the frame
    solid moon {
        disc = Circle(center=(-18, 0), radius=34)
        hole bite {
            c = Circle(center=(-8, 8), radius=28)
        }
    }
    # the moon's back reaches 3 mm into the frame
    moon.disc.left.x == frame.window.c.left.x - 3 mm
    AlignCenterY(moon.disc, frame.window)
}
