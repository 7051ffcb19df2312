-- Two equal cylinders stacked face to face (a shaft on a hub).
return cylinder{r=30, h=30} + cylinder{r=30, h=30}:translate(0, 0, 30)
