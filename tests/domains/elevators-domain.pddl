; Elevators-like (after IPC 2008 elevators): travel costs depend on the floors (action costs
; with a static numeric fluent); the cheap way up is floor by floor.
(define (domain elevators)
  (:requirements :typing :action-costs)
  (:types floor passenger)
  (:predicates (lift-at ?f - floor) (at ?p - passenger ?f - floor) (boarded ?p - passenger))
  (:functions (total-cost) - number (travel ?a ?b - floor) - number)
  (:action move
    :parameters (?a ?b - floor)
    :precondition (lift-at ?a)
    :effect (and (lift-at ?b) (not (lift-at ?a)) (increase (total-cost) (travel ?a ?b))))
  (:action board
    :parameters (?p - passenger ?f - floor)
    :precondition (and (lift-at ?f) (at ?p ?f))
    :effect (and (boarded ?p) (not (at ?p ?f)) (increase (total-cost) 1)))
  (:action leave
    :parameters (?p - passenger ?f - floor)
    :precondition (and (lift-at ?f) (boarded ?p))
    :effect (and (at ?p ?f) (not (boarded ?p)) (increase (total-cost) 1))))
