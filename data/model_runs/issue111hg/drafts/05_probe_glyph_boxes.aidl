units mm
solid a { w = Text("#JONESWED", (0, 0), size=50, font="sans:Bold") }
solid b { w = Text("#", (0, 100), size=50, font="sans:Bold") 
          hole x { c = Circle(center=(300, 300), radius=1) } }
solid c { w = Text("J", (0, 200), size=50, font="sans:Bold") }
