; `either` in an action's parameters restricts what the action applies to: refused, line named.
(define (domain either-action)
  (:requirements :typing)
  (:types cup plate - object)
  (:predicates (washed ?x - object))
  (:action wash
    :parameters (?x - (either cup plate))
    :precondition (not (washed ?x))
    :effect (washed ?x)))
