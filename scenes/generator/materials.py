"""Materials: diffuse reflectances (RGB, all within 0.1 .. 0.8) and the lights' emission."""

OFF_WHITE = (0.74, 0.72, 0.66)
CEILING = (0.80, 0.80, 0.78)
OAK_FLOOR = (0.55, 0.40, 0.26)
LINOLEUM = (0.42, 0.46, 0.48)
CARPET = (0.36, 0.34, 0.40)
PALE_BLUE = (0.60, 0.66, 0.72)
WARM_WALL = (0.76, 0.70, 0.60)
WOOD = (0.62, 0.46, 0.30)
DARK_WOOD = (0.36, 0.25, 0.17)
BIRCH = (0.72, 0.64, 0.50)
STEEL = (0.45, 0.46, 0.48)
RED_FABRIC = (0.62, 0.18, 0.14)
BLUE_FABRIC = (0.22, 0.32, 0.55)
GREEN_FABRIC = (0.24, 0.46, 0.28)
GREY_FABRIC = (0.42, 0.42, 0.44)
ORANGE_PLASTIC = (0.78, 0.45, 0.15)
BLUE_PLASTIC = (0.20, 0.36, 0.62)
WHITE_PAINT = (0.78, 0.78, 0.76)
BLACK_TV = (0.10, 0.10, 0.11)
DOOR = (0.50, 0.34, 0.20)
WINDOW = (0.28, 0.36, 0.46)
BLACKBOARD = (0.12, 0.22, 0.16)
LEAVES = (0.20, 0.44, 0.16)
TERRACOTTA = (0.60, 0.32, 0.20)
LAMP = (0.80, 0.80, 0.80)  # reflectance of the emitting light panels
CONCRETE = (0.58, 0.57, 0.55)
STAGE = (0.45, 0.30, 0.22)
POSTERS = [(0.70, 0.30, 0.25), (0.25, 0.45, 0.65), (0.75, 0.65, 0.25), (0.35, 0.55, 0.35),
           (0.55, 0.35, 0.60), (0.70, 0.55, 0.45)]
BOOKS = [(0.55, 0.15, 0.15), (0.15, 0.25, 0.50), (0.20, 0.40, 0.22), (0.70, 0.60, 0.30),
         (0.40, 0.20, 0.40)]
LIGHT_EMISSION = (10.0, 10.0, 9.0)  # ceiling panels of scenes 0-3, slightly warm white
